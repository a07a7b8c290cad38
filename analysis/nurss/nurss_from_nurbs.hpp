#pragma once
// A quadratic NURSS from quadratic (order 3 x 3) NURBS control nets, and n-gon faces for the holes.
//
// The paper's correspondence between a quadratic B-spline and knot intervals: control point P_i stands
// for one polynomial segment, the middle interval of its basis function's support,
//     d_i = t_{i+2} - t_{i+1}   (knots t_0 .. t_{n+2}, 0-based),
// so P_ij holds d_i on its two u edges and e_j (the same from the v knots) on its two v edges. A clamped
// end gives its end row d = 0 (a crease: the net's boundary curve is the surface's); a double interior
// knot gives its control point d = 0 (the C0 joint of two arcs stays a crease). Each quad of the net
// (P_ij, P_i+1,j, P_i+1,j+1, P_i,j+1) is one face, counter-clockwise when Su x Sv points outward.
// Rational nets are taken as they are: the NURSS vertices keep the weights (nurss_mesh.hpp).
#include <vector>

#include "core/nurss_mesh.hpp"
#include "core/nurbs_surface.hpp"

namespace cadnurbs {

// The nets of `surfaces` as one mesh: faces of surface s in order (quad (i, j) before (i+1, j), rows
// j in order), control points within `weld_tolerance` of each other and of equal weight (relative 1e-9)
// becoming one vertex (a closed profile's seam, nets that share a boundary). Refuses (GeometryError) a
// surface that is not order 3 in both directions or is invalid, a quad whose corners weld together (a
// pole), a side that two nets would both use in the same direction, and welded edges whose nets give
// different knot intervals (boundaries parametrised differently: no one NURSS reproduces both).
NurssMesh nurss_from_nurbs(const std::vector<NurbsSurface>& surfaces, double weld_tolerance = 0);

// Closes every boundary loop of `mesh` with one n-gon face running against the loop (the capping's
// handrail connections as n-gons instead of trimmed lids, seed 001 §5.2), labelled `label`. The new
// face's sides are the loop's edges, whose intervals are already set. Returns the new faces, in the
// order of their first boundary edge. Refuses (GeometryError) a boundary vertex on two loops and a loop
// of fewer than 3 edges.
std::vector<NurssFaceId> fill_boundary_loops(NurssMesh& mesh, int label = 1);

}  // namespace cadnurbs
