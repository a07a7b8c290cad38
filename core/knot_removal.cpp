#include "core/knot_removal.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/knot_vector.hpp"

namespace cadnurbs {

namespace {

// Homogeneous control points (w·(P - c), w) of one curve; a surface is a set of rows sharing knots.
using Row = std::vector<Eigen::Vector4d>;

// What turns a removal's homogeneous mismatch into a bound on the Euclidean move (see the header).
struct MoveBound {
  bool rational = false;
  double radius = 0;      // R: bounds |C - c| over the whole removal sequence
  double min_weight = 1;  // a lower bound of every weight of the current net
};

struct Candidate {
  std::vector<Row> rows;
  double bound = 0;       // how far the curve or surface may move by this removal
  double min_weight = 1;  // lower bound of the weights after it
};

// Removes one occurrence of knots[r] (its last occurrence; multiplicity s <= degree) from every row.
// Empty when the equations cannot be solved or a weight would not stay positive.
std::optional<Candidate> remove_once(const std::vector<double>& U, int order, const std::vector<Row>& rows, int r, int s,
                                     const MoveBound& mb) {
  const int p = order - 1;
  const int count = static_cast<int>(rows[0].size());
  const double u = U[r];
  const int first = r - p, last = r - s;
  if (s > p || first < 1 || last + 1 >= count) return std::nullopt;
  auto alpha = [&](int i) { return (u - U[i]) / (U[i + p + 1] - U[i]); };
  Candidate out;
  out.min_weight = mb.min_weight;
  double worst = 0.0;
  std::vector<Eigen::Vector4d> L(count + 1), R(count + 1);
  for (const Row& P : rows) {
    // P_i = a_i Q_i + (1 - a_i) Q_{i-1} for i in [first, last]; Q_{first-1} = P_{first-1} and
    // Q_last = P_{last+1}. Solved from the left (L) and from the right (R) until they meet.
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
    // The mismatch δ: both ends reached Q_j, or one equation is left over.
    const Eigen::Vector4d delta = j < i ? Eigen::Vector4d(L[j] - R[j])
                                        : Eigen::Vector4d(P[i] - (alpha(i) * R[i] + (1.0 - alpha(i)) * L[i - 1]));
    worst = std::max(worst, mb.rational ? delta.head<3>().norm() + mb.radius * std::abs(delta.w()) : delta.head<3>().norm());
    Row q;
    q.reserve(count - 1);
    for (int k = 0; k < first; ++k) q.push_back(P[k]);
    for (int k = first; k < last; ++k) {
      q.push_back(k < i ? L[k] : R[k]);
      out.min_weight = std::min(out.min_weight, q.back().w());
    }
    for (int k = last + 1; k < count; ++k) q.push_back(P[k]);
    out.rows.push_back(std::move(q));
  }
  if (!std::isfinite(worst)) return std::nullopt;
  if (mb.rational) {
    if (!(out.min_weight > 0)) return std::nullopt;
    worst /= out.min_weight;
  }
  out.bound = worst;
  return out;
}

// One pass over the interior knots from the left; removes what the budget allows. Returns how many.
int removal_pass(std::vector<double>& U, int order, std::vector<Row>& rows, double& budget, MoveBound& mb) {
  int count = 0;
  for (int r = order; r < static_cast<int>(rows[0].size()); ++r) {
    if (U[r] == U[r + 1]) continue;  // r must be the last occurrence of its value
    int s = 1;
    while (s < r && U[r - s] == U[r]) ++s;
    if (U[r] <= U[order - 1] || U[r] >= U[rows[0].size()]) continue;
    auto candidate = remove_once(U, order, rows, r, s, mb);
    if (!candidate || candidate->bound > budget) continue;
    budget -= candidate->bound;
    rows = std::move(candidate->rows);
    mb.min_weight = candidate->min_weight;
    U.erase(U.begin() + r);
    ++count;
  }
  return count;
}

// The bound's constants for control points `points` (Euclidean) with `weights` (empty: polynomial).
MoveBound move_bound(const std::vector<Eigen::Vector3d>& points, const std::vector<double>& weights, double tolerance,
                     Eigen::Vector3d& centre) {
  Eigen::AlignedBox3d box;
  for (const auto& q : points) box.extend(q);
  centre = box.center();
  MoveBound mb;
  mb.rational = !weights.empty();
  for (const auto& q : points) mb.radius = std::max(mb.radius, (q - centre).norm());
  mb.radius += tolerance;
  if (mb.rational) mb.min_weight = *std::min_element(weights.begin(), weights.end());
  return mb;
}

Eigen::Vector4d homogeneous(const Eigen::Vector3d& q, double w, const Eigen::Vector3d& centre) {
  Eigen::Vector4d h;
  h << w * (q - centre), w;
  return h;
}

Eigen::Vector3d euclidean(const Eigen::Vector4d& h, const Eigen::Vector3d& centre) { return h.head<3>() / h.w() + centre; }

// Parameters at which a result is compared with its input: every distinct knot of the input's domain
// and `per_span` points inside each span, at most about `most` in all.
std::vector<double> check_parameters(const std::vector<double>& knots, int order, int count, int per_span, int most) {
  const std::vector<double> breaks = domain_breaks(knots, order, count);
  const int spans = std::max<int>(1, static_cast<int>(breaks.size()) - 1);
  const int per = std::max(1, std::min(per_span, most / spans));
  std::vector<double> t;
  for (size_t k = 0; k + 1 < breaks.size(); ++k)
    for (int q = 0; q < per; ++q) t.push_back(breaks[k] + (breaks[k + 1] - breaks[k]) * q / per);
  t.push_back(breaks.back());
  return t;
}

double sampled_distance(const NurbsCurve& a, const NurbsCurve& b) {
  double worst = 0.0;
  for (double t : check_parameters(a.knots, a.order, a.count(), 8, 1 << 20))
    worst = std::max(worst, (curve_point(a, t) - curve_point(b, t)).norm());
  return worst;
}

double sampled_distance(const NurbsSurface& a, const NurbsSurface& b) {
  double worst = 0.0;
  const auto us = check_parameters(a.u_knots, a.u_order, a.u_count, 4, 256);
  const auto vs = check_parameters(a.v_knots, a.v_order, a.v_count, 4, 256);
  for (double u : us)
    for (double v : vs) worst = std::max(worst, (surface_point(a, u, v) - surface_point(b, u, v)).norm());
  return worst;
}

}  // namespace

NurbsCurve remove_knots(const NurbsCurve& curve, double tolerance, int* removed) {
  if (removed) *removed = 0;
  if (curve.order < 2 || !(tolerance > 0)) return curve;
  Eigen::Vector3d centre;
  MoveBound mb = move_bound(curve.points, curve.weights, tolerance, centre);
  std::vector<Row> rows(1);
  for (int i = 0; i < curve.count(); ++i) rows[0].push_back(homogeneous(curve.points[i], curve.weight(i), centre));
  std::vector<double> knots = curve.knots;
  double budget = tolerance;
  int count = 0;
  while (const int n = removal_pass(knots, curve.order, rows, budget, mb)) count += n;
  if (count == 0) return curve;
  NurbsCurve out = curve;
  out.knots = std::move(knots);
  out.points.clear();
  out.weights.clear();
  for (const auto& h : rows[0]) {
    out.points.push_back(euclidean(h, centre));
    if (curve.is_rational()) out.weights.push_back(h.w());
  }
  if (curve.dimension == 2)
    for (auto& q : out.points) q.z() = 0.0;
  if (sampled_distance(curve, out) > tolerance) return curve;
  if (removed) *removed = count;
  return out;
}

NurbsSurface remove_knots(const NurbsSurface& surface, double tolerance, int* removed) {
  if (removed) *removed = 0;
  if (surface.u_order < 2 || surface.v_order < 2 || !(tolerance > 0)) return surface;
  Eigen::Vector3d centre;
  MoveBound mb = move_bound(surface.points, surface.weights, tolerance, centre);
  int nu = surface.u_count, nv = surface.v_count;
  std::vector<double> uk = surface.u_knots, vk = surface.v_knots;
  // rows[j][i] (rows along u) while removing u knots; columns[i][j] while removing v knots.
  std::vector<Row> rows(nv, Row(nu));
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) rows[j][i] = homogeneous(surface.point(i, j), surface.weight(i, j), centre);
  const auto transposed = [](const std::vector<Row>& m) {
    std::vector<Row> t(m[0].size(), Row(m.size()));
    for (size_t a = 0; a < m.size(); ++a)
      for (size_t b = 0; b < m[0].size(); ++b) t[b][a] = m[a][b];
    return t;
  };
  double budget = tolerance;
  int count = 0;
  for (bool progress = true; progress;) {
    const int in_u = removal_pass(uk, surface.u_order, rows, budget, mb);
    nu -= in_u;
    std::vector<Row> columns = transposed(rows);
    const int in_v = removal_pass(vk, surface.v_order, columns, budget, mb);
    nv -= in_v;
    rows = transposed(columns);
    count += in_u + in_v;
    progress = in_u + in_v > 0;
  }
  if (count == 0) return surface;
  NurbsSurface out = surface;
  out.u_count = nu;
  out.v_count = nv;
  out.u_knots = std::move(uk);
  out.v_knots = std::move(vk);
  out.points.clear();
  out.weights.clear();
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      out.points.push_back(euclidean(rows[j][i], centre));
      if (surface.is_rational()) out.weights.push_back(rows[j][i].w());
    }
  if (sampled_distance(surface, out) > tolerance) return surface;
  if (removed) *removed = count;
  return out;
}

}  // namespace cadnurbs
