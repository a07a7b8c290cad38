#include "analysis/eval/rational_derivative_bound.hpp"

#include <algorithm>
#include <limits>

namespace cadnurbs {

RationalDerivativeBound rational_derivative_bound(const BernsteinPolynomial<Eigen::Vector3d>& g,
                                                  const BernsteinPolynomial<double>& w, double du, double dv) {
  RationalDerivativeBound out;
  double w_min = std::numeric_limits<double>::infinity();
  for (const double x : w.c) w_min = std::min(w_min, x);
  const auto gu = bernstein_derivative(g, true, du), gv = bernstein_derivative(g, false, dv);
  const auto wu = bernstein_derivative(w, true, du), wv = bernstein_derivative(w, false, dv);
  const auto a_u = bernstein_sum(bernstein_product(gu, w), bernstein_product(g, wu), -1.0);  // S_u W^2
  const auto a_v = bernstein_sum(bernstein_product(gv, w), bernstein_product(g, wv), -1.0);
  out.u = largest_coefficient(a_u) / (w_min * w_min);
  out.v = largest_coefficient(a_v) / (w_min * w_min);
  const auto guu = bernstein_derivative(gu, true, du), guv = bernstein_derivative(gu, false, dv);
  const auto gvv = bernstein_derivative(gv, false, dv);
  const auto wuu = bernstein_derivative(wu, true, du), wuv = bernstein_derivative(wu, false, dv);
  const auto wvv = bernstein_derivative(wv, false, dv);
  const double w3 = w_min * w_min * w_min;
  // (X W - 2 W_d A): the numerator over W^3 of a second derivative, X its first part.
  auto numerator = [&](const BernsteinPolynomial<Eigen::Vector3d>& x, const BernsteinPolynomial<double>& w_d,
                       const BernsteinPolynomial<Eigen::Vector3d>& a) {
    return bernstein_sum(bernstein_product(x, w), bernstein_scaled(bernstein_product(a, w_d), 2.0), -1.0);
  };
  out.uu = largest_coefficient(numerator(bernstein_sum(bernstein_product(guu, w), bernstein_product(g, wuu), -1.0), wu, a_u)) / w3;
  out.vv = largest_coefficient(numerator(bernstein_sum(bernstein_product(gvv, w), bernstein_product(g, wvv), -1.0), wv, a_v)) / w3;
  const auto x_uv = bernstein_sum(
      bernstein_sum(bernstein_sum(bernstein_product(guv, w), bernstein_product(gu, wv)), bernstein_product(gv, wu), -1.0),
      bernstein_product(g, wuv), -1.0);
  out.uv = largest_coefficient(numerator(x_uv, wv, a_u)) / w3;
  return out;
}

}  // namespace cadnurbs
