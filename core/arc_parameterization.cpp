#include "core/arc_parameterization.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/geometry_error.hpp"

namespace cadnurbs {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// The span holding x (an angle or a parameter: both equal at knots), clamped to the arc.
int span_of(const ArcSpans& arc, double x) {
  const double w = (arc.end - arc.start) / arc.spans;
  int k = std::clamp(static_cast<int>(std::floor((x - arc.start) / w)), 0, arc.spans - 1);
  if (k > 0 && x < arc_knot(arc, k)) --k;
  if (k < arc.spans - 1 && x > arc_knot(arc, k + 1)) ++k;
  return k;
}

// Angle swept from a span end after local parameter s (0 <= s <= 1/2) measured from that end, for a
// span with t = tan(h/2): off/2 = h/2 + atan(t (2s - 1)), whose tangent is 2 t s / (1 - t^2 (2s - 1)).
// Measured from the end nearer s, so that both ends come out exact (s = 0 gives 0).
double swept_angle(double s, double t) { return 2 * std::atan2(2 * t * s, 1 - t * t * (2 * s - 1)); }

// Its inverse: with T = tan(off/2), s = T (1 + t^2) / (2 t (1 + T t)).
double local_parameter(double off, double t) {
  const double big_t = std::tan(off / 2);
  return big_t * (1 + t * t) / (2 * t * (1 + big_t * t));
}

}  // namespace

ArcSpans arc_spans(double start_angle, double end_angle) {
  if (!std::isfinite(start_angle) || !std::isfinite(end_angle)) throw GeometryError("arc", "its angles are not finite");
  const double sweep = end_angle - start_angle;
  if (!(sweep > 0))
    throw GeometryError("arc", "its end angle " + std::to_string(end_angle) + " does not exceed its start angle " +
                                   std::to_string(start_angle));
  if (sweep > kTwoPi + 1e-9) throw GeometryError("arc", "its sweep " + std::to_string(sweep) + " exceeds 2 pi");
  const int spans = std::clamp(static_cast<int>(std::ceil(sweep / (std::numbers::pi / 2) - 1e-9)), 1, 4);
  return {start_angle, end_angle, spans};
}

double arc_knot(const ArcSpans& arc, int k) {
  if (k <= 0) return arc.start;
  if (k >= arc.spans) return arc.end;
  return arc.start + k * (arc.end - arc.start) / arc.spans;
}

double arc_parameter(const ArcSpans& arc, double angle) {
  angle = std::clamp(angle, arc.start, arc.end);
  const int k = span_of(arc, angle);
  const double k0 = arc_knot(arc, k), k1 = arc_knot(arc, k + 1);
  const double width = k1 - k0, t = std::tan(width / 4);
  if (angle - k0 <= width / 2) return k0 + local_parameter(angle - k0, t) * width;
  return k1 - local_parameter(k1 - angle, t) * width;
}

double arc_angle(const ArcSpans& arc, double parameter) {
  parameter = std::clamp(parameter, arc.start, arc.end);
  const int k = span_of(arc, parameter);
  const double k0 = arc_knot(arc, k), k1 = arc_knot(arc, k + 1);
  const double width = k1 - k0, t = std::tan(width / 4);
  if (parameter - k0 <= width / 2) return k0 + swept_angle((parameter - k0) / width, t);
  return k1 - swept_angle((k1 - parameter) / width, t);
}

NurbsCurve unit_arc(const ArcSpans& arc) {
  NurbsCurve curve;
  curve.dimension = 2;
  curve.order = 3;
  curve.knots = {arc.start, arc.start, arc.start};
  curve.points.emplace_back(std::cos(arc.start), std::sin(arc.start), 0.0);
  curve.weights.push_back(1.0);
  for (int k = 0; k < arc.spans; ++k) {
    const double k0 = arc_knot(arc, k), k1 = arc_knot(arc, k + 1);
    const double c = (k0 + k1) / 2, h = (k1 - k0) / 2;
    curve.points.emplace_back(std::cos(c) / std::cos(h), std::sin(c) / std::cos(h), 0.0);
    curve.weights.push_back(std::cos(h));
    curve.points.emplace_back(std::cos(k1), std::sin(k1), 0.0);
    curve.weights.push_back(1.0);
    const int multiplicity = k + 1 < arc.spans ? 2 : 3;
    curve.knots.insert(curve.knots.end(), multiplicity, k1);
  }
  if (std::abs(arc.end - arc.start - kTwoPi) <= 1e-12) curve.points.back() = curve.points.front();
  return curve;
}

}  // namespace cadnurbs
