#include "core/loop_closure.hpp"

#include "core/geometry_error.hpp"

namespace cadnurbs {

namespace {

enum class SegmentEnd { start, end };

// True when the first (or last) `order` knots are equal: the curve ends at its first (or last) control
// point, which can then be moved alone.
bool clamped_at(const NurbsCurve& c, SegmentEnd end) {
  const size_t m = c.knots.size();
  auto knot = [&](int i) { return end == SegmentEnd::start ? c.knots[i] : c.knots[m - 1 - i]; };
  for (int i = 1; i < c.order; ++i)
    if (knot(i) != knot(0)) return false;
  return true;
}

void move_end(TrimSegment& segment, SegmentEnd end, const Eigen::Vector2d& p) {
  const bool start = end == SegmentEnd::start;
  if (auto* c = std::get_if<NurbsCurve>(&segment)) {
    if (!clamped_at(*c, end))
      throw GeometryError("trim segment", start ? "start is not clamped; cannot move it" : "end is not clamped; cannot move it");
    (start ? c->points.front() : c->points.back()) = Eigen::Vector3d(p.x(), p.y(), 0.0);
  } else {
    auto& points = std::get<Polyline2D>(segment).points;
    (start ? points.front() : points.back()) = p;
  }
}

}  // namespace

void join_segments(TrimSegment& a, TrimSegment& b) {
  const Eigen::Vector2d mid = 0.5 * (segment_end(a) + segment_start(b));
  move_end(a, SegmentEnd::end, mid);
  move_end(b, SegmentEnd::start, mid);
}

void close_loop_gaps(TrimLoop& loop, double tolerance, const std::vector<int>& trim_numbers,
                     const std::string& loop_name) {
  const std::size_t n = loop.segments.size();
  for (std::size_t i = 0; i < n; ++i) {
    TrimSegment& a = loop.segments[i];
    TrimSegment& b = loop.segments[(i + 1) % n];
    const double gap = (segment_end(a) - segment_start(b)).norm();
    if (gap > tolerance)
      throw GeometryError(loop_name, "does not close: gap " + std::to_string(gap) + " after trim " +
                                         std::to_string(trim_numbers.at(i)) + " exceeds the tolerance " +
                                         std::to_string(tolerance));
    if (gap > 0) join_segments(a, b);
  }
}

}  // namespace cadnurbs
