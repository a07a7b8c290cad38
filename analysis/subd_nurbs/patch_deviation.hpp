#pragma once
// How far a fitted patch lies from the Catmull-Clark limit surface, at equal (u, v) (internal to
// analysis/subd_nurbs).
//
// Proven where the limit is bicubic: on each regular piece of the patch (SubdLimitSurface::pieces), cut
// along the fit's knots, both are cubic polynomials in u and v, so their difference is one too, and its
// largest value is at most the largest of its Bezier coefficients (a convex combination of them): the
// coefficients of both restricted to the rectangle (blossoming), subtracted. Sampled on the end caps (the
// squares of side 2^-10 at extraordinary features, where OpenSubdiv's Gregory patch stands in for the
// limit): 5 x 5 points each.
#include "analysis/subd_nurbs/rhino_limit_surface.hpp"
#include "core/nurbs_surface.hpp"

namespace cadnurbs::subd_nurbs {

struct PatchDeviation {
  double proven = 0;   // bound over the regular pieces
  double sampled = 0;  // largest sampled distance over the end caps (0 when there are none)
};

// `fit`: a polynomial bicubic surface over [0, 1]^2 (orders 4).
PatchDeviation patch_deviation(const NurbsSurface& fit, const RhinoLimitSurface& limit, int patch);

// The Bezier points (index i + 4 j, u fastest) of a uniform bicubic B-spline patch of 4 x 4 points.
std::array<Eigen::Vector3d, 16> bicubic_bezier_points(const std::array<Eigen::Vector3d, 16>& bspline);

}  // namespace cadnurbs::subd_nurbs
