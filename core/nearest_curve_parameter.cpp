#include "core/nearest_curve_parameter.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace cadnurbs {

namespace {

// Newton's iteration from t while the distance descends, kept inside the domain.
double newton_nearest(const NurbsCurve& curve, const Eigen::Vector3d& p, double t) {
  const double a = curve.domain_start(), b = curve.domain_end();
  for (int iteration = 0; iteration < 30; ++iteration) {
    const auto d = curve_derivatives(curve, t, 2);
    const Eigen::Vector3d r = d[0] - p;
    const double f = r.dot(d[1]), df = d[1].squaredNorm() + r.dot(d[2]);
    if (!(df > 0)) break;
    const double next = std::clamp(t - f / df, a, b);
    if ((curve_point(curve, next) - p).squaredNorm() > r.squaredNorm()) break;  // no longer descending
    const bool done = std::abs(next - t) <= 1e-15 * (b - a);
    t = next;
    if (done) break;
  }
  return t;
}

}  // namespace

double nearest_curve_parameter(const NurbsCurve& curve, const Eigen::Vector3d& p) {
  const double a = curve.domain_start(), b = curve.domain_end();
  // Start: the nearest of (order + 2) samples per knot span.
  double t = a, best = std::numeric_limits<double>::infinity();
  const int per_span = curve.order + 2;
  for (std::size_t k = static_cast<std::size_t>(curve.order - 1); k < curve.points.size(); ++k) {
    const double s0 = curve.knots[k], s1 = curve.knots[k + 1];
    if (!(s1 > s0)) continue;
    for (int i = 0; i <= per_span; ++i) {
      const double s = s0 + (s1 - s0) * i / per_span;
      const double d = (curve_point(curve, s) - p).squaredNorm();
      if (d < best) best = d, t = s;
    }
  }
  return newton_nearest(curve, p, t);
}

std::vector<double> curve_parameters_near(const NurbsCurve& curve, const Eigen::Vector3d& p, double within) {
  constexpr int kPerSpan = 64;
  std::vector<double> s;
  for (std::size_t k = static_cast<std::size_t>(curve.order - 1); k < curve.points.size(); ++k) {
    const double s0 = curve.knots[k], s1 = curve.knots[k + 1];
    if (!(s1 > s0)) continue;
    for (int i = s.empty() ? 0 : 1; i <= kPerSpan; ++i) s.push_back(s0 + (s1 - s0) * i / kPerSpan);
  }
  std::vector<double> d(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) d[i] = (curve_point(curve, s[i]) - p).norm();
  std::vector<double> out;
  const double span = curve.domain_end() - curve.domain_start();
  for (std::size_t i = 0; i < s.size(); ++i) {
    if ((i > 0 && d[i - 1] < d[i]) || (i + 1 < s.size() && d[i + 1] < d[i])) continue;
    const double t = newton_nearest(curve, p, s[i]);
    if ((curve_point(curve, t) - p).norm() > within) continue;
    if (!out.empty() && std::abs(out.back() - t) <= 1e-12 * span) continue;
    out.push_back(t);
  }
  return out;
}

}  // namespace cadnurbs
