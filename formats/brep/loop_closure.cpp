#include "formats/brep/loop_closure.hpp"

#include "core/geometry_error.hpp"

namespace cadnurbs {

namespace {

bool clamped_at_start(const NurbsCurve& c) {
  for (int i = 1; i < c.order; ++i)
    if (c.knots[i] != c.knots[0]) return false;
  return true;
}

bool clamped_at_end(const NurbsCurve& c) {
  const size_t m = c.knots.size();
  for (int i = 1; i < c.order; ++i)
    if (c.knots[m - 1 - i] != c.knots[m - 1]) return false;
  return true;
}

void set_end(TrimSegment& segment, const Eigen::Vector2d& p) {
  if (auto* c = std::get_if<NurbsCurve>(&segment)) {
    if (!clamped_at_end(*c)) throw GeometryError("trim segment", "end is not clamped; cannot move it");
    c->points.back() = Eigen::Vector3d(p.x(), p.y(), 0.0);
  } else {
    std::get<Polyline2D>(segment).points.back() = p;
  }
}

void set_start(TrimSegment& segment, const Eigen::Vector2d& p) {
  if (auto* c = std::get_if<NurbsCurve>(&segment)) {
    if (!clamped_at_start(*c)) throw GeometryError("trim segment", "start is not clamped; cannot move it");
    c->points.front() = Eigen::Vector3d(p.x(), p.y(), 0.0);
  } else {
    std::get<Polyline2D>(segment).points.front() = p;
  }
}

}  // namespace

void join_segments(TrimSegment& a, TrimSegment& b) {
  const Eigen::Vector2d mid = 0.5 * (segment_end(a) + segment_start(b));
  set_end(a, mid);
  set_start(b, mid);
}

}  // namespace cadnurbs
