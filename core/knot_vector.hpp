#pragma once
// Knot vectors and B-spline basis functions (Piegl & Tiller, The NURBS Book, A2.1-A2.3).
// A knot vector for `count` control points of order `order` (degree order-1) has count+order values.
#include <string>
#include <vector>

namespace cadnurbs {

// Empty string when `knots` is a valid knot vector for `count` control points of `order`;
// otherwise a sentence naming the fault (wrong length, decreasing knot, too high multiplicity...).
std::string knot_vector_fault(const std::vector<double>& knots, int order, int count);

// Index of the knot span holding t, clamped to the valid domain [knots[order-1], knots[count]].
// Result s satisfies knots[s] <= t < knots[s+1] (the last non-empty span for t at the end).
int find_knot_span(const std::vector<double>& knots, int order, int count, double t);

// The `order` non-zero basis functions at t in span `span`, and their derivatives up to `max_derivative`.
// Returns ders[k][j] = k-th derivative of N_{span-order+1+j}, k <= max_derivative, j < order.
std::vector<std::vector<double>> basis_function_derivatives(const std::vector<double>& knots, int order,
                                                            int span, double t, int max_derivative);

// The same into caller storage, without allocating for orders up to kMaxStackOrder: ders[k * stride + j],
// stride >= order. The kernel of the evaluators (curve_point, SurfaceEvaluator).
constexpr int kMaxStackOrder = 26;
void basis_function_derivatives(const std::vector<double>& knots, int order, int span, double t, int max_derivative,
                                double* ders, int stride);

// A clamped uniform knot vector on [0, 1] for `count` control points of `order`.
std::vector<double> clamped_uniform_knots(int order, int count);

// Distinct knot values and their multiplicities.
struct KnotMultiplicity {
  double value;
  int multiplicity;
};
std::vector<KnotMultiplicity> knot_multiplicities(const std::vector<double>& knots);

// The distinct values of a non-decreasing knot vector, in order.
std::vector<double> distinct_knots(const std::vector<double>& knots);

// The distinct knot values in the domain [knots[order-1], knots[count]], both ends included: the
// boundaries of the Bezier pieces (a curve or surface is polynomial, or rational, between two of them).
std::vector<double> domain_breaks(const std::vector<double>& knots, int order, int count);

// The interior knot values of the domain (ends excluded) repeated at least degree (order - 1) times:
// the only places where the curve or surface may be merely C0 (a corner), so the only lines a bound on
// second derivatives must not be applied across.
std::vector<double> c0_knots(const std::vector<double>& knots, int order, int count);

}  // namespace cadnurbs
