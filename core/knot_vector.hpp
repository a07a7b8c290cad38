#pragma once
// Knot vectors and B-spline basis functions (Piegl & Tiller, The NURBS Book, A2.1-A2.3).
// A knot vector for `count` control points of order `order` (degree order-1) has count+order values.
#include <algorithm>
#include <string>
#include <vector>

namespace cadnurbs {

// Empty string when `knots` is a valid knot vector for `count` control points of `order`;
// otherwise a sentence naming the fault (wrong length, decreasing knot, too high multiplicity...).
std::string knot_vector_fault(const std::vector<double>& knots, int order, int count);

// Index of the knot span holding t, clamped to the valid domain [knots[order-1], knots[count]].
// Result s satisfies knots[s] <= t < knots[s+1] (the last non-empty span for t at the end).
// Inline: the evaluators call it for every point.
inline int find_knot_span(const std::vector<double>& knots, int order, int count, double t) {
  const int p = order - 1;
  const int n = count - 1;
  if (t >= knots[n + 1]) {
    // Last non-empty span.
    int s = n;
    while (s > p && knots[s] == knots[s + 1]) --s;
    return s;
  }
  if (t <= knots[p]) {
    int s = p;
    while (s < n && knots[s] == knots[s + 1]) ++s;
    return s;
  }
  // knots[span] <= t < knots[span+1]
  auto it = std::upper_bound(knots.begin() + p, knots.begin() + n + 2, t);
  return static_cast<int>(it - knots.begin()) - 1;
}

// The `order` non-zero basis functions at t in span `span`, and their derivatives up to `max_derivative`.
// Returns ders[k][j] = k-th derivative of N_{span-order+1+j}, k <= max_derivative, j < order.
std::vector<std::vector<double>> basis_function_derivatives(const std::vector<double>& knots, int order,
                                                            int span, double t, int max_derivative);

// The same into caller storage, without allocating for orders up to kMaxStackOrder: ders[k * stride + j],
// stride >= order. The kernel of the evaluators (curve_point, SurfaceEvaluator).
constexpr int kMaxStackOrder = 26;
void basis_function_derivatives(const std::vector<double>& knots, int order, int span, double t, int max_derivative,
                                double* ders, int stride);

// The values alone (A2.2: one row instead of the triangle of A2.3) into n[0 .. order-1], with scratch
// left, right of `order` doubles each: basis_function_derivatives with max_derivative 0 runs this, so
// the two agree bit for bit. Inline, so that an evaluator that knows the order at compile time gets
// it unrolled.
inline void basis_function_values(const double* knots, int order, int span, double t, double* n, double* left,
                                  double* right) {
  n[0] = 1.0;
  for (int j = 1; j < order; ++j) {
    left[j] = t - knots[span + 1 - j];
    right[j] = knots[span + j] - t;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      const double temp = n[r] / (right[r + 1] + left[j - r]);
      n[r] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    n[j] = saved;
  }
}

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
