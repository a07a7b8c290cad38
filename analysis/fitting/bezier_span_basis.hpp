#pragma once
// The rational Bézier re-parametrisation of seed 003 §4, one knot span at a time: over the span
// [u_s, u_{s+1}] each of the `order` B-spline basis functions that live there is a polynomial, whose
// Bernstein coefficients on the local parameter u' = (t - u_s) / (u_{s+1} - u_s) in [0, 1] depend only
// on the 2 * degree knots u_{s-degree+1} .. u_{s+degree}. Templated on the scalar so that a dual number
// carries their derivatives with respect to one knot (forward mode), which is how the fitting energy
// gets its knot gradient exactly. Also the Bernstein polynomials and a one-derivative dual number.
#include <cmath>

namespace cadnurbs {

// a + b·ε with ε² = 0: value and derivative with respect to one chosen variable.
struct Dual {
  double value = 0;
  double derivative = 0;
};
inline Dual operator+(Dual a, Dual b) { return {a.value + b.value, a.derivative + b.derivative}; }
inline Dual operator-(Dual a, Dual b) { return {a.value - b.value, a.derivative - b.derivative}; }
inline Dual operator*(Dual a, Dual b) { return {a.value * b.value, a.derivative * b.value + a.value * b.derivative}; }
inline Dual operator/(Dual a, Dual b) {
  return {a.value / b.value, (a.derivative * b.value - a.value * b.derivative) / (b.value * b.value)};
}
inline Dual operator-(double a, Dual b) { return Dual{a, 0} - b; }
inline Dual operator*(double a, Dual b) { return {a * b.value, a * b.derivative}; }

// local_knots: u_{s-degree+1} .. u_{s+degree} (2 * degree values, u_s < u_{s+1} in the middle).
// Writes coefficients[r * order + i] = the r-th Bernstein coefficient (r = 0..degree) of the basis
// function N_{s-degree+i} (i = 0..degree) on the span. Each coefficient is a blossom value of the basis
// function, degree - r arguments u_s and r arguments u_{s+1}, found by de Boor's recurrence with those
// arguments (Piegl & Tiller §5.2; de Boor's algorithm evaluates the blossom when its levels take
// different arguments). Cost order^4 operations; refuses nothing (the caller guarantees u_s < u_{s+1}).
template <class Scalar>
void bezier_span_basis(const Scalar* local_knots, int order, Scalar* coefficients) {
  const int degree = order - 1;
  const Scalar start = local_knots[degree - 1];
  const Scalar end = local_knots[degree];
  // knot(j) = u_{s-degree+j} for j = 1 .. 2 * degree.
  auto knot = [&](int j) -> const Scalar& { return local_knots[j - 1]; };
  constexpr int kMaxOrder = 16;
  Scalar points[kMaxOrder][kMaxOrder];  // points[j][i]: de Boor point j's coefficient of basis function i
  for (int r = 0; r <= degree; ++r) {
    for (int j = 0; j <= degree; ++j) {
      for (int i = 0; i <= degree; ++i) points[j][i] = Scalar{i == j ? 1.0 : 0.0};
    }
    for (int level = 1; level <= degree; ++level) {
      const Scalar& argument = level <= degree - r ? start : end;
      for (int j = degree; j >= level; --j) {
        const Scalar alpha = (argument - knot(j)) / (knot(j + degree - level + 1) - knot(j));
        for (int i = 0; i <= degree; ++i) points[j][i] = (1.0 - alpha) * points[j - 1][i] + alpha * points[j][i];
      }
    }
    for (int i = 0; i <= degree; ++i) coefficients[r * order + i] = points[degree][i];
  }
}

// The Bernstein polynomials of `degree` at u in [0, 1] and their first two derivatives:
// values[d * (degree + 1) + r] = d-th derivative of B_r at u, d = 0..2 (zero where d > degree).
inline void bernstein_with_derivatives(int degree, double u, double* values) {
  const int n = degree + 1;
  // Pascal-style build up to degree - 2, degree - 1 and degree; derivatives from the lower degrees:
  // B'_{r,p} = p (B_{r-1,p-1} - B_{r,p-1}), B''_{r,p} = p (p-1) (B_{r-2,p-2} - 2 B_{r-1,p-2} + B_{r,p-2}).
  constexpr int kMaxOrder = 16;
  double lower2[kMaxOrder + 2] = {};
  double lower1[kMaxOrder + 2] = {};
  double row[kMaxOrder + 2] = {};
  row[0] = 1;
  for (int p = 1; p <= degree; ++p) {
    for (int r = 0; r < p; ++r) lower2[r] = lower1[r];
    for (int r = 0; r < p; ++r) lower1[r] = row[r];
    row[p] = 0;
    for (int r = p; r >= 0; --r) row[r] = (1 - u) * row[r] + (r > 0 ? u * row[r - 1] : 0.0);
  }
  if (degree == 0) lower1[0] = 0;
  for (int r = 0; r < n; ++r) {
    values[r] = row[r];
    const double d1 = degree >= 1 ? degree * ((r > 0 ? lower1[r - 1] : 0.0) - (r < degree ? lower1[r] : 0.0)) : 0.0;
    double d2 = 0;
    if (degree >= 2) {
      const double a = r >= 2 ? lower2[r - 2] : 0.0;
      const double b = (r >= 1 && r - 1 <= degree - 2) ? lower2[r - 1] : 0.0;
      const double c = r <= degree - 2 ? lower2[r] : 0.0;
      d2 = degree * (degree - 1) * (a - 2 * b + c);
    }
    values[n + r] = d1;
    values[2 * n + r] = d2;
  }
}

}  // namespace cadnurbs
