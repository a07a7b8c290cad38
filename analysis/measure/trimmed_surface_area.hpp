#pragma once
// Area of a trimmed NURBS surface: the integral of |Su x Sv| over the trimmed (u,v) domain.
//
// The domain is the constrained Delaunay triangulation (CGAL) of the loops sampled as polygons plus
// a grid on every knot line, Delaunay in coordinates where an average knot span is a unit square, so
// most triangles lie inside one Bézier patch, where the integrand is smooth; each triangle gets a collapsed (Duffy) 6 x 6 Gauss-Legendre rule. The thin regions
// between each polygon chord and its trimming curve are added (or taken away) exactly as curved
// strips, parametrised by (chord to curve) x (along the chord) with their own Gauss rule, so the
// polygon never limits the accuracy. Sampling and grid are doubled until two successive estimates
// agree to `relative_tolerance`.
#include "core/trimmed_surface.hpp"

namespace cadnurbs {

// Area in the surface's units squared. Refuses (GeometryError) an invalid surface or a tolerance
// <= 0; when 7 doublings do not converge it returns the last estimate.
double trimmed_surface_area(const TrimmedSurface& surface, double relative_tolerance = 1e-9);

}  // namespace cadnurbs
