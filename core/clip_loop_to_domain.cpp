#include "core/clip_loop_to_domain.hpp"

#include <algorithm>
#include <cmath>

#include "core/point_in_loops.hpp"
#include "core/polygon_2d.hpp"
#include "core/segment_piece.hpp"
#include "core/trim_segment_parameters.hpp"

namespace cadnurbs {

namespace {

struct Piece {
  int segment;
  double t0, t1;
  bool inside;
};

// A run of the loop inside the box: from where it enters to where it leaves (both on the box's sides).
struct Run {
  std::vector<TrimSegment> segments;
  Eigen::Vector2d entry, exit;
  double entry_at = 0, exit_at = 0;  // perimeter positions (perimeter_position)
};

class Box {
 public:
  explicit Box(const DomainBox& b) : b_(b) {}
  bool contains(const Eigen::Vector2d& p) const { return p.x() >= b_.u0 && p.x() <= b_.u1 && p.y() >= b_.v0 && p.y() <= b_.v1; }
  // The side p lies nearest to (0 bottom, 1 right, 2 top, 3 left: counter-clockwise from (u0, v0)).
  int side(const Eigen::Vector2d& p) const {
    const double d[4] = {std::abs(p.y() - b_.v0) / dv(), std::abs(p.x() - b_.u1) / du(), std::abs(p.y() - b_.v1) / dv(),
                         std::abs(p.x() - b_.u0) / du()};
    return static_cast<int>(std::min_element(d, d + 4) - d);
  }
  // p put on its nearest side exactly.
  Eigen::Vector2d snapped(const Eigen::Vector2d& p) const {
    Eigen::Vector2d q(std::clamp(p.x(), b_.u0, b_.u1), std::clamp(p.y(), b_.v0, b_.v1));
    switch (side(p)) {
      case 0: q.y() = b_.v0; break;
      case 1: q.x() = b_.u1; break;
      case 2: q.y() = b_.v1; break;
      default: q.x() = b_.u0;
    }
    return q;
  }
  // Position along the boundary, counter-clockwise from (u0, v0): side k covers [k, k + 1].
  double perimeter_position(const Eigen::Vector2d& p) const {
    const int k = side(p);
    const double f = k == 0 ? (p.x() - b_.u0) / du() : k == 1 ? (p.y() - b_.v0) / dv() : k == 2 ? (b_.u1 - p.x()) / du()
                                                                                                   : (b_.v1 - p.y()) / dv();
    return k + std::clamp(f, 0.0, 1.0);
  }
  Eigen::Vector2d corner(int k) const {
    switch (((k % 4) + 4) % 4) {
      case 0: return {b_.u0, b_.v0};
      case 1: return {b_.u1, b_.v0};
      case 2: return {b_.u1, b_.v1};
      default: return {b_.u0, b_.v1};
    }
  }
  double du() const { return b_.u1 - b_.u0; }
  double dv() const { return b_.v1 - b_.v0; }

 private:
  DomainBox b_;
};

// The loop's pieces, each wholly inside or outside the box, in loop order.
std::vector<Piece> pieces_of(const TrimLoop& loop, const Box& box, int samples_per_span) {
  std::vector<Piece> pieces;
  for (size_t k = 0; k < loop.segments.size(); ++k) {
    const TrimSegment& s = loop.segments[k];
    const std::vector<double> breaks = segment_breaks(s);
    std::vector<double> ts;
    for (size_t i = 0; i + 1 < breaks.size(); ++i)
      for (int j = 0; j < samples_per_span; ++j) ts.push_back(breaks[i] + (breaks[i + 1] - breaks[i]) * j / samples_per_span);
    ts.push_back(breaks.back());
    std::vector<double> cuts = {ts.front()};
    bool previous = box.contains(segment_uv(s, ts.front()));
    for (size_t i = 1; i < ts.size(); ++i) {
      const bool now = box.contains(segment_uv(s, ts[i]));
      if (now == previous) continue;
      double a = ts[i - 1], b = ts[i];  // inside status `previous` at a, `now` at b
      for (int it = 0; it < 200 && a < b; ++it) {
        const double m = 0.5 * (a + b);
        if (m <= a || m >= b) break;
        (box.contains(segment_uv(s, m)) == previous ? a : b) = m;
      }
      cuts.push_back(0.5 * (a + b));
      previous = now;
    }
    cuts.push_back(ts.back());
    const double span = ts.back() - ts.front();
    for (size_t i = 0; i + 1 < cuts.size(); ++i) {
      if (!(cuts[i + 1] - cuts[i] > 1e-12 * span)) continue;
      pieces.push_back({static_cast<int>(k), cuts[i], cuts[i + 1], box.contains(segment_uv(s, 0.5 * (cuts[i] + cuts[i + 1])))});
    }
  }
  return pieces;
}

}  // namespace

std::vector<TrimLoop> clip_loop_to_domain(const TrimLoop& loop, const DomainBox& domain, int samples_per_span) {
  const Box box(domain);
  const std::vector<Piece> pieces = pieces_of(loop, box, samples_per_span);
  const bool counter_clockwise = polygon_signed_area(loop_polygon(loop)) > 0;
  const auto first_out = std::find_if(pieces.begin(), pieces.end(), [](const Piece& p) { return !p.inside; });
  if (first_out == pieces.end()) return {loop};
  const auto any_in = std::find_if(pieces.begin(), pieces.end(), [](const Piece& p) { return p.inside; });
  if (any_in == pieces.end()) {
    // The loop misses the box: it holds all of it or none.
    if (!PointInLoops({loop_polygon(loop)}).inside(box.corner(0) + 0.5 * Eigen::Vector2d(box.du(), box.dv()))) return {};
    Polyline2D boundary;
    for (int k = 0; k <= 4; ++k) boundary.points.push_back(box.corner(counter_clockwise ? k : -k));
    TrimLoop whole;
    whole.segments.emplace_back(std::move(boundary));
    return {whole};
  }
  // Runs of inside pieces, starting after the first outside piece.
  std::vector<Run> runs;
  const size_t n = pieces.size(), start = static_cast<size_t>(first_out - pieces.begin());
  for (size_t i = 0; i < n; ++i) {
    const Piece& p = pieces[(start + i) % n];
    if (!p.inside) continue;
    const Piece& before = pieces[(start + i + n - 1) % n];
    if (!before.inside) runs.emplace_back();
    runs.back().segments.push_back(segment_piece(loop.segments[p.segment], p.t0, p.t1));
    const Eigen::Vector2d at_start = segment_uv(loop.segments[p.segment], p.t0), at_end = segment_uv(loop.segments[p.segment], p.t1);
    if (!before.inside) runs.back().entry = box.snapped(at_start);
    runs.back().exit = box.snapped(at_end);
  }
  for (Run& r : runs) {
    set_segment_start(r.segments.front(), r.entry);
    set_segment_end(r.segments.back(), r.exit);
    r.entry_at = box.perimeter_position(r.entry);
    r.exit_at = box.perimeter_position(r.exit);
  }
  // Each run's exit joins, along the sides in the loop's direction, the nearest entry ahead.
  auto gap = [&](double from, double to) { return std::fmod((counter_clockwise ? to - from : from - to) + 8.0, 4.0); };
  std::vector<TrimLoop> out;
  std::vector<bool> used(runs.size(), false);
  for (size_t first = 0; first < runs.size(); ++first) {
    if (used[first]) continue;
    TrimLoop clipped;
    size_t r = first;
    for (size_t guard = 0; guard <= runs.size(); ++guard) {
      used[r] = true;
      for (const auto& s : runs[r].segments) clipped.segments.push_back(s);
      size_t next = r;
      double best = 5;
      for (size_t q = 0; q < runs.size(); ++q) {
        const double g = gap(runs[r].exit_at, runs[q].entry_at);
        if (g < best && (!used[q] || q == first)) best = g, next = q;
      }
      Polyline2D side{{runs[r].exit}};
      const double from = runs[r].exit_at;
      if (counter_clockwise)
        for (double c = std::floor(from) + 1; c < from + best; c += 1) side.points.push_back(box.corner(static_cast<int>(c)));
      else
        for (double c = std::ceil(from) - 1; c > from - best; c -= 1) side.points.push_back(box.corner(static_cast<int>(c)));
      side.points.push_back(runs[next].entry);
      if (side.points.size() > 2 || side.points.front() != side.points.back()) clipped.segments.emplace_back(std::move(side));
      r = next;
      if (r == first) break;
    }
    out.push_back(std::move(clipped));
  }
  return out;
}

}  // namespace cadnurbs
