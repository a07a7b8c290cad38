#pragma once
// Tensor-product Bernstein polynomials on one Bézier piece, and the algebra the rational derivative
// bounds need: derivatives, products, degree elevation, sums. A curve is a piece with n = 0.
//
// In: coefficients c[i + j * (m + 1)] of degree (m, n), u fastest; T is double or Eigen::Vector3d.
// Why it is used: a polynomial on its piece lies in the convex hull of its coefficients, so
// largest_coefficient() bounds |f| there; written over a common denominator, terms that cancel in the
// true function cancel in the coefficients too (the S_uv of a cylinder is exactly 0).
// Product: Farin, "Curves and Surfaces for CAGD", the product of Bernstein forms,
// c_k = sum_i C(m1, i) C(m2, k - i) / C(m1 + m2, k) a_i b_{k-i}, per direction.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/binomial.hpp"

namespace cadnurbs {

template <class T>
struct BernsteinPolynomial {
  int m = 0, n = 0;  // degrees in u and in v
  std::vector<T> c;  // (m + 1) x (n + 1), u fastest
  BernsteinPolynomial(int m_, int n_, const T& zero) : m(m_), n(n_), c(static_cast<size_t>((m_ + 1) * (n_ + 1)), zero) {}
  T& at(int i, int j) { return c[i + j * (m + 1)]; }
  const T& at(int i, int j) const { return c[i + j * (m + 1)]; }
};

namespace bernstein_detail {
inline double zero_of(double) { return 0.0; }
inline Eigen::Vector3d zero_of(const Eigen::Vector3d&) { return Eigen::Vector3d::Zero(); }
inline double magnitude(double x) { return std::abs(x); }
inline double magnitude(const Eigen::Vector3d& x) { return x.norm(); }
}  // namespace bernstein_detail

// d/du (along_u) or d/dv in the global parameter, the piece spanning `span` in that direction. A
// polynomial of degree 0 there has derivative 0 (kept at degree 0).
template <class T>
BernsteinPolynomial<T> bernstein_derivative(const BernsteinPolynomial<T>& a, bool along_u, double span) {
  const T zero = bernstein_detail::zero_of(a.c[0]);
  if ((along_u ? a.m : a.n) == 0) return BernsteinPolynomial<T>(a.m, a.n, zero);
  BernsteinPolynomial<T> d(a.m - (along_u ? 1 : 0), a.n - (along_u ? 0 : 1), zero);
  const double f = (along_u ? a.m : a.n) / span;
  for (int j = 0; j <= d.n; ++j)
    for (int i = 0; i <= d.m; ++i) d.at(i, j) = f * (along_u ? a.at(i + 1, j) - a.at(i, j) : a.at(i, j + 1) - a.at(i, j));
  return d;
}

// a * b, of degree (a.m + b.m, a.n + b.n); T is the type of a's coefficients, b's are scalars.
template <class T>
BernsteinPolynomial<T> bernstein_product(const BernsteinPolynomial<T>& a, const BernsteinPolynomial<double>& b) {
  BernsteinPolynomial<T> out(a.m + b.m, a.n + b.n, bernstein_detail::zero_of(a.c[0]));
  auto factors = [](int m1, int m2) {  // C(m1, i1) C(m2, i2) / C(m1 + m2, i1 + i2)
    std::vector<double> f(static_cast<size_t>((m1 + 1) * (m2 + 1)));
    for (int i1 = 0; i1 <= m1; ++i1)
      for (int i2 = 0; i2 <= m2; ++i2) f[i1 * (m2 + 1) + i2] = binomial(m1, i1) * binomial(m2, i2) / binomial(m1 + m2, i1 + i2);
    return f;
  };
  const std::vector<double> fu = factors(a.m, b.m), fv = factors(a.n, b.n);
  for (int j1 = 0; j1 <= a.n; ++j1)
    for (int i1 = 0; i1 <= a.m; ++i1)
      for (int j2 = 0; j2 <= b.n; ++j2)
        for (int i2 = 0; i2 <= b.m; ++i2)
          out.at(i1 + i2, j1 + j2) += T(fu[i1 * (b.m + 1) + i2] * fv[j1 * (b.n + 1) + j2] * (a.at(i1, j1) * b.at(i2, j2)));
  return out;
}

// The same polynomial at degree (m, n) >= its own (degree elevation, one step at a time).
template <class T>
BernsteinPolynomial<T> bernstein_elevated(BernsteinPolynomial<T> a, int m, int n) {
  const T zero = bernstein_detail::zero_of(a.c[0]);
  while (a.m < m) {
    BernsteinPolynomial<T> e(a.m + 1, a.n, zero);
    for (int j = 0; j <= a.n; ++j)
      for (int i = 0; i <= e.m; ++i) {
        const double f = static_cast<double>(i) / e.m;
        e.at(i, j) = (i > 0 ? T(f * a.at(i - 1, j)) : zero) + (i < e.m ? T((1 - f) * a.at(i, j)) : zero);
      }
    a = std::move(e);
  }
  while (a.n < n) {
    BernsteinPolynomial<T> e(a.m, a.n + 1, zero);
    for (int j = 0; j <= e.n; ++j)
      for (int i = 0; i <= a.m; ++i) {
        const double f = static_cast<double>(j) / e.n;
        e.at(i, j) = (j > 0 ? T(f * a.at(i, j - 1)) : zero) + (j < e.n ? T((1 - f) * a.at(i, j)) : zero);
      }
    a = std::move(e);
  }
  return a;
}

// a + sign * b at the larger of the two degrees (a zero derivative keeps its parent's degree).
template <class T>
BernsteinPolynomial<T> bernstein_sum(const BernsteinPolynomial<T>& a, const BernsteinPolynomial<T>& b, double sign = 1.0) {
  BernsteinPolynomial<T> r = bernstein_elevated(a, std::max(a.m, b.m), std::max(a.n, b.n));
  const BernsteinPolynomial<T> e = bernstein_elevated(b, r.m, r.n);
  for (size_t k = 0; k < r.c.size(); ++k) r.c[k] = r.c[k] + sign * e.c[k];
  return r;
}

template <class T>
BernsteinPolynomial<T> bernstein_scaled(BernsteinPolynomial<T> a, double f) {
  for (auto& x : a.c) x = T(f * x);
  return a;
}

// max |coefficient|: a bound on |a| over its piece (convex hull).
template <class T>
double largest_coefficient(const BernsteinPolynomial<T>& a) {
  double r = 0;
  for (const auto& x : a.c) r = std::max(r, bernstein_detail::magnitude(x));
  return r;
}

}  // namespace cadnurbs
