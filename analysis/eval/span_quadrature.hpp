#pragma once
// The quadrature rules the fitting energies integrate fairness with, one knot span at a time (seed 003
// §5): Gauss-Legendre inside ordinary spans, Simpson's rule in spans so short that knots crowd there.
// Shared by curve_fit_energy and fit_surface so that both integrate the same way.
#include <vector>

namespace cadnurbs {

struct QuadratureRule {
  std::vector<double> nodes;    // on [0, 1]
  std::vector<double> weights;  // summing to 1
};

// Gauss-Legendre with `count` >= 1 nodes on [0, 1]: exact for polynomials up to degree 2 count - 1.
// Computed once per count (thread-safe); the reference stays valid for the program's life.
const QuadratureRule& gauss_legendre(int count);

// Simpson's rule on [0, 1]: it samples the span's ends, where Gauss nodes in a crowd of short spans
// would miss what happens at the knots.
const QuadratureRule& simpson();

// The rule for a span of `length` when knots are kept `minimum_gap` apart: Simpson when the span is at
// most 4 gaps long (crowded), else Gauss-Legendre with `order` nodes (exact for the bending integrand
// of a polynomial spline of that order).
const QuadratureRule& fairness_rule(double length, double minimum_gap, int order);

}  // namespace cadnurbs
