#pragma once
// Bounds on the first and second derivatives of one rational Bézier piece, from the Bernstein
// coefficients of their numerators over a common denominator.
//
// In: the piece in homogeneous form, G = w (P - c) (c any centre; the control points' mean keeps the
// coefficients small) and W = w, as Bernstein polynomials of degree (p, q) (a curve: q = 0), and its
// spans du, dv in the global parameters. Out: bounds on |S_u|, |S_v|, |S_uu|, |S_uv|, |S_vv| over the
// piece. Refuses nothing; weights must be positive (W >= the smallest weight then).
//
// Why the bounds hold: S_u = A_u / W^2 with A_u = G_u W - G W_u, and
// S_uu = ((G_uu W - G W_uu) W - 2 W_u A_u) / W^3,
// S_uv = ((G_uv W + G_u W_v - G_v W_u - G W_uv) W - 2 W_v A_u) / W^3,
// each numerator a polynomial bounded by its largest coefficient (bernstein_polynomial.hpp). Unlike the
// quotient rule applied to bounds, terms that cancel in the true derivative cancel here: a cylinder's
// S_uv and a ruled patch's S_uu come out 0, not a multiple of the patch's radius.
#include <Eigen/Core>

#include "core/bernstein_polynomial.hpp"

namespace cadnurbs {

struct RationalDerivativeBound {
  double u = 0, v = 0;           // |S_u|, |S_v|
  double uu = 0, uv = 0, vv = 0;  // |S_uu|, |S_uv|, |S_vv|
};

RationalDerivativeBound rational_derivative_bound(const BernsteinPolynomial<Eigen::Vector3d>& g,
                                                  const BernsteinPolynomial<double>& w, double du, double dv);

}  // namespace cadnurbs
