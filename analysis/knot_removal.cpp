#include "analysis/knot_removal.hpp"

#include <optional>

namespace cadnurbs {

namespace {

struct Removal {
  NurbsCurve curve;
  double error = 0.0;
};

// Removes one occurrence of the knot at index r (its last occurrence; multiplicity s) from a
// non-rational curve.
std::optional<Removal> remove_once(const NurbsCurve& c, int r, int s) {
  const int p = c.order - 1;
  const auto& U = c.knots;
  const auto& P = c.points;
  const double u = U[r];
  const int first = r - p, last = r - s;
  if (first < 1 || last + 1 >= c.count()) return std::nullopt;
  auto alpha = [&](int i) { return (u - U[i]) / (U[i + p + 1] - U[i]); };
  // Knot insertion gives P_i = a_i Q_i + (1 - a_i) Q_{i-1} for i in [first, last]; Q_{first-1} = P_{first-1}
  // and Q_last = P_{last+1}. Solve from the left (L) and from the right (R) until they meet.
  std::vector<Eigen::Vector3d> L(c.count() + 1), R(c.count() + 1);
  L[first - 1] = P[first - 1];
  R[last] = P[last + 1];
  int i = first, j = last;
  while (j - i > 0) {
    const double ai = alpha(i), aj = alpha(j);
    if (ai == 0.0 || aj == 1.0) return std::nullopt;
    L[i] = (P[i] - (1.0 - ai) * L[i - 1]) / ai;
    R[j - 1] = (P[j] - aj * R[j]) / (1.0 - aj);
    ++i;
    --j;
  }
  double error;
  if (j < i) {
    error = (L[j] - R[j]).norm();  // both ends reached Q_j
  } else {
    const double ai = alpha(i);
    error = (P[i] - (ai * R[i] + (1.0 - ai) * L[i - 1])).norm();  // one equation left over
  }
  Removal out;
  out.error = error;
  out.curve = c;
  out.curve.points.clear();
  for (int k = 0; k < first; ++k) out.curve.points.push_back(P[k]);
  for (int k = first; k < last; ++k) out.curve.points.push_back(k < i ? L[k] : R[k]);
  for (int k = last + 1; k < c.count(); ++k) out.curve.points.push_back(P[k]);
  out.curve.knots.erase(out.curve.knots.begin() + r);
  return out;
}

double sampled_distance(const NurbsCurve& a, const NurbsCurve& b) {
  double worst = 0.0;
  for (size_t k = static_cast<size_t>(a.order - 1); k < a.points.size(); ++k) {
    const double t0 = a.knots[k], t1 = a.knots[k + 1];
    if (t1 <= t0) continue;
    for (int q = 0; q <= 8; ++q) {
      const double t = t0 + (t1 - t0) * q / 8.0;
      worst = std::max(worst, (curve_point(a, t) - curve_point(b, t)).norm());
    }
  }
  return worst;
}

}  // namespace

NurbsCurve remove_knots(const NurbsCurve& curve, double tolerance, int* removed) {
  if (removed) *removed = 0;
  if (curve.is_rational() || curve.order < 2 || !(tolerance > 0)) return curve;
  NurbsCurve current = curve;
  double budget = tolerance;
  int count = 0;
  for (bool progress = true; progress;) {
    progress = false;
    // Interior knots, from the left; r is the last occurrence of each value.
    for (int r = current.order; r < current.count(); ++r) {
      if (current.knots[r] == current.knots[r + 1]) continue;
      int s = 1;
      while (s < r && current.knots[r - s] == current.knots[r]) ++s;
      if (current.knots[r] <= current.domain_start() || current.knots[r] >= current.domain_end()) continue;
      auto removal = remove_once(current, r, s);
      if (!removal || removal->error > budget) continue;
      budget -= removal->error;
      current = std::move(removal->curve);
      ++count;
      progress = true;
    }
  }
  if (count == 0) return curve;
  if (sampled_distance(curve, current) > tolerance) return curve;
  if (removed) *removed = count;
  return current;
}

}  // namespace cadnurbs
