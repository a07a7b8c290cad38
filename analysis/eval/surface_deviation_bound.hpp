#pragma once
// Rigorous bounds on how far a flat triangle in a surface's (u,v) domain lies from the surface.
//
// Filip, Magedson & Markot, "Surface algorithms using bounds on derivatives" (CAGD 3, 1986): if the
// second derivatives of S are bounded by M_uu, M_uv, M_vv on a region, the linear interpolant L of S
// at the corners of a (u,v) triangle satisfies |S - L| <= (1/2) max_x sum_i lambda_i(x) Q(a_i - x),
// Q(d) = M_uu d_u^2 + 2 M_uv |d_u d_v| + M_vv d_v^2 (Taylor at x with the integral remainder). With
// 2|d_u d_v| <= t d_u^2 + d_v^2 / t, Q becomes a diagonal quadratic form; after scaling the axes it is
// |d|^2, and max_x sum_i lambda_i |a_i - x|^2 = R^2 - dist(c, T)^2 (c, R: circumcentre and radius).
// For the right triangle of an h_u x h_v grid cell this is exactly FMM's (1/8)(h_u^2 M_uu +
// 2 h_u h_v M_uv + h_v^2 M_vv).
//
// Rational patches: the second derivatives of S = G / W (G = w (P - c), W = w, polynomial in
// homogeneous form) are bounded through the quotient rule with the Bézier bounds of G, W and their
// first derivatives, |S - c| <= R and W >= w_min (the homogeneous-form bound as used by Zheng &
// Sederberg, "Estimating tessellation parameter intervals for rational curves and surfaces", 2000).
// On patches of degree <= 3 each way (conics, the analytic surfaces) the numerators of the second
// derivatives over W^3 are bounded too (rational_derivative_bound.hpp) and the smaller bound is kept:
// there what cancels in the true derivative (a cylinder's S_uv) cancels in the bound.
// Bézier bounds: |d^2 G/du^2| <= p (p - 1) / du^2 max |second differences of the net|, and so on.
//
// The bound needs S to be C1 across the triangle: knot lines of multiplicity >= degree (C0) split
// triangles before the bound is applied (see c0_u / c0_v).
#include <Eigen/Core>
#include <vector>

#include "core/nurbs_surface.hpp"

namespace cadnurbs {

struct SecondDerivativeBound {
  double uu = 0, uv = 0, vv = 0;
};

// Bounds per Bézier patch of a surface, on the grid of its distinct knot values.
struct SurfaceDeviationBound {
  std::vector<double> u_breaks, v_breaks;       // distinct knot values inside the domain, ends included
  std::vector<SecondDerivativeBound> patches;   // (u_breaks.size()-1) x (v_breaks.size()-1), u fastest
  std::vector<double> c0_u, c0_v;               // interior knot values where S may be only C0

  // The largest bound over the patches meeting the box [u0, u1] x [v0, v1].
  SecondDerivativeBound over(double u0, double u1, double v0, double v1) const;
};

// Second-derivative bounds of every Bézier patch of `surface` (validated).
SurfaceDeviationBound surface_deviation_bound(const NurbsSurface& surface);

// (1/2) max over the triangle of sum_i lambda_i Q(a_i - x) for the bound m: the largest distance
// between S and its linear interpolant on triangle (a, b, c), if S is C1 there with these bounds.
double triangle_deviation_bound(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                                const SecondDerivativeBound& m);

}  // namespace cadnurbs
