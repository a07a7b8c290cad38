#include "core/loop_self_crossing.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/polygon_2d.hpp"
#include "core/segment_piece.hpp"
#include "core/trim_segment_parameters.hpp"

namespace cadnurbs {

namespace {

// Where each chord of the sampled loop lies: from point k to the next, on segment `segment` over
// [t, t_next].
struct ChordSource {
  int segment;
  double t, t_next;
};

// The loop sampled as loop_polygon samples it (each NURBS knot span `samples_per_span` times, polyline
// vertices as they are), with where each chord lies.
void sample_loop(const TrimLoop& loop, int samples_per_span, std::vector<Eigen::Vector2d>& points,
                 std::vector<ChordSource>& sources) {
  for (size_t k = 0; k < loop.segments.size(); ++k) {
    const TrimSegment& segment = loop.segments[k];
    const int steps = std::holds_alternative<NurbsCurve>(segment) ? samples_per_span : 1;
    const std::vector<double> breaks = segment_breaks(segment);
    for (size_t i = 0; i + 1 < breaks.size(); ++i) {
      const double a = breaks[i], b = breaks[i + 1];
      for (int s = 0; s < steps; ++s) {
        const double t = a + (b - a) * s / steps;
        points.push_back(segment_uv(segment, t));
        sources.push_back({static_cast<int>(k), t, s + 1 == steps ? b : a + (b - a) * (s + 1) / steps});
      }
    }
  }
}

double orientation(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

// The first pair (i < j) of non-adjacent chords of the closed polygon that properly cross, by more
// than `tolerance`. Chords sorted by their smallest u and swept, so only chords whose u ranges overlap
// are compared. Zero-length chords (a pole's degenerate piece) cross nothing.
std::optional<std::pair<size_t, size_t>> crossing_chords(const std::vector<Eigen::Vector2d>& poly, double tolerance) {
  const size_t n = poly.size();
  if (n < 4) return std::nullopt;
  auto lo = [&](size_t i) { return std::min(poly[i].x(), poly[(i + 1) % n].x()); };
  auto hi = [&](size_t i) { return std::max(poly[i].x(), poly[(i + 1) % n].x()); };
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return lo(a) < lo(b); });
  std::vector<size_t> active;
  for (size_t i : order) {
    const Eigen::Vector2d &a = poly[i], &b = poly[(i + 1) % n];
    if (a == b) continue;
    const double start = lo(i);
    active.erase(std::remove_if(active.begin(), active.end(), [&](size_t j) { return hi(j) < start; }), active.end());
    for (size_t j : active) {
      if ((i + 1) % n == j || (j + 1) % n == i) continue;
      const Eigen::Vector2d &c = poly[j], &d = poly[(j + 1) % n];
      // Orientations are distances from the line times the chord's length.
      const double ab = (b - a).norm() * tolerance, cd = (d - c).norm() * tolerance;
      const double o1 = orientation(a, b, c), o2 = orientation(a, b, d);
      const double o3 = orientation(c, d, a), o4 = orientation(c, d, b);
      if (((o1 > ab && o2 < -ab) || (o1 < -ab && o2 > ab)) && ((o3 > cd && o4 < -cd) || (o3 < -cd && o4 > cd)))
        return std::make_pair(std::min(i, j), std::max(i, j));
    }
    active.push_back(i);
  }
  return std::nullopt;
}

}  // namespace

bool polygon_crosses_itself(const std::vector<Eigen::Vector2d>& polygon, double tolerance) {
  return crossing_chords(polygon, tolerance).has_value();
}

std::optional<LoopSelfCrossing> find_self_crossing(const TrimLoop& loop, int samples_per_span, double tolerance) {
  std::vector<Eigen::Vector2d> points;
  std::vector<ChordSource> sources;
  sample_loop(loop, samples_per_span, points, sources);
  const auto pair = crossing_chords(points, tolerance);
  if (!pair) return std::nullopt;
  const size_t n = points.size();
  const auto [i, j] = *pair;
  const ChordSource &ci = sources[i], &cj = sources[j];
  // The chords' crossing: a + s (b - a) = c + r (d - c).
  const Eigen::Vector2d a = points[i], b = points[(i + 1) % n], c = points[j], d = points[(j + 1) % n];
  Eigen::Matrix2d m;
  m << b - a, c - d;
  const Eigen::Vector2d sr = m.colPivHouseholderQr().solve(c - a);
  LoopSelfCrossing x;
  x.first = ci.segment;
  x.second = cj.segment;
  x.first_t = ci.t + std::clamp(sr.x(), 0.0, 1.0) * (ci.t_next - ci.t);
  x.second_t = cj.t + std::clamp(sr.y(), 0.0, 1.0) * (cj.t_next - cj.t);
  // Newton on the curves, kept only while it stays on the two chords' pieces and closes the gap.
  const TrimSegment &sa = loop.segments[x.first], &sb = loop.segments[x.second];
  double ta = x.first_t, tb = x.second_t;
  Eigen::Vector2d residual = segment_uv(sa, ta) - segment_uv(sb, tb);
  for (int iteration = 0; iteration < 20 && residual.norm() > 0; ++iteration) {
    Eigen::Matrix2d jacobian;
    jacobian << segment_tangent(sa, ta), -segment_tangent(sb, tb);
    const Eigen::Vector2d step = jacobian.colPivHouseholderQr().solve(residual);
    const double na = ta - step.x(), nb = tb - step.y();
    if (!(na >= ci.t && na <= ci.t_next && nb >= cj.t && nb <= cj.t_next)) break;
    const Eigen::Vector2d next = segment_uv(sa, na) - segment_uv(sb, nb);
    if (!(next.norm() < residual.norm())) break;
    ta = na, tb = nb, residual = next;
  }
  x.first_t = ta, x.second_t = tb;
  x.point = 0.5 * (segment_uv(sa, ta) + segment_uv(sb, tb));
  std::vector<Eigen::Vector2d> between{x.point}, outer{x.point};
  for (size_t k = i + 1; k <= j; ++k) between.push_back(points[k]);
  for (size_t k = j + 1; k < n + i + 1; ++k) outer.push_back(points[k % n]);
  x.between_area = polygon_signed_area(between);
  x.outer_area = polygon_signed_area(outer);
  return x;
}

TrimLoop cut_lobe(const TrimLoop& loop, const LoopSelfCrossing& x, KeptLobe kept) {
  TrimLoop out;
  const bool refs = !loop.edges.empty();
  auto keep = [&](int k) {
    out.segments.push_back(loop.segments[k]);
    if (refs) out.edges.push_back(loop.edges[k]);
  };
  // A piece of a cut segment; nothing when it is empty (the crossing at the segment's end).
  auto piece = [&](int k, double t0, double t1) {
    const TrimSegment& s = loop.segments[k];
    const double span = segment_t1(s) - segment_t0(s);
    if (!(t1 - t0 > 1e-12 * span)) return;
    out.segments.push_back(segment_piece(s, t0, t1));
    if (refs) out.edges.push_back({});
  };
  const TrimSegment &a = loop.segments[x.first], &b = loop.segments[x.second];
  const int count = static_cast<int>(loop.segments.size());
  if (kept == KeptLobe::outer) {
    for (int k = 0; k < x.first; ++k) keep(k);
    piece(x.first, segment_t0(a), x.first_t);
    const size_t joint = out.segments.size();
    piece(x.second, x.second_t, segment_t1(b));
    for (int k = x.second + 1; k < count; ++k) keep(k);
    // The pieces meet at the crossing point exactly.
    if (joint > 0) set_segment_end(out.segments[joint - 1], x.point);
    if (joint < out.segments.size()) set_segment_start(out.segments[joint], x.point);
  } else {
    if (x.first == x.second) {
      piece(x.first, x.first_t, x.second_t);
    } else {
      piece(x.first, x.first_t, segment_t1(a));
      for (int k = x.first + 1; k < x.second; ++k) keep(k);
      piece(x.second, segment_t0(b), x.second_t);
    }
    if (!out.segments.empty()) set_segment_start(out.segments.front(), x.point), set_segment_end(out.segments.back(), x.point);
  }
  return out;
}

}  // namespace cadnurbs
