#include "core/trim_segment_parameters.hpp"

#include <algorithm>

#include "core/knot_vector.hpp"

namespace cadnurbs {

double segment_t0(const TrimSegment& segment) {
  if (const auto* c = std::get_if<NurbsCurve>(&segment)) return c->domain_start();
  return 0.0;
}

double segment_t1(const TrimSegment& segment) {
  if (const auto* c = std::get_if<NurbsCurve>(&segment)) return c->domain_end();
  return static_cast<double>(std::get<Polyline2D>(segment).points.size() - 1);
}

Eigen::Vector2d segment_uv(const TrimSegment& segment, double t) {
  if (const auto* c = std::get_if<NurbsCurve>(&segment)) return curve_point(*c, t).head<2>();
  const auto& pts = std::get<Polyline2D>(segment).points;
  const double tt = std::clamp(t, 0.0, static_cast<double>(pts.size() - 1));
  const size_t i = std::min(static_cast<size_t>(tt), pts.size() - 2);
  const double f = tt - static_cast<double>(i);
  if (f == 0.0) return pts[i];
  if (f == 1.0) return pts[i + 1];
  return (1 - f) * pts[i] + f * pts[i + 1];
}

Eigen::Vector2d segment_tangent(const TrimSegment& segment, double t) {
  if (const auto* c = std::get_if<NurbsCurve>(&segment)) return curve_derivatives(*c, t, 1)[1].head<2>();
  const auto& pts = std::get<Polyline2D>(segment).points;
  const double tt = std::clamp(t, 0.0, static_cast<double>(pts.size() - 1));
  const size_t i = std::min(static_cast<size_t>(tt), pts.size() - 2);
  return pts[i + 1] - pts[i];
}

std::vector<double> segment_breaks(const TrimSegment& segment) {
  if (const auto* c = std::get_if<NurbsCurve>(&segment)) return domain_breaks(c->knots, c->order, c->count());
  std::vector<double> out;
  const size_t n = std::get<Polyline2D>(segment).points.size();
  for (size_t i = 0; i < n; ++i) out.push_back(static_cast<double>(i));
  return out;
}

std::vector<double> segment_kinks(const TrimSegment& segment) {
  const auto* c = std::get_if<NurbsCurve>(&segment);
  if (!c) return segment_breaks(segment);
  std::vector<double> out{c->domain_start()};
  for (double k : c0_knots(c->knots, c->order, c->count())) out.push_back(k);
  out.push_back(c->domain_end());
  return out;
}

}  // namespace cadnurbs
