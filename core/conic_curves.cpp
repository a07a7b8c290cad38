#include "core/conic_curves.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/arc_parameterization.hpp"
#include "core/geometry_error.hpp"

namespace cadnurbs {
namespace {

void check_radius(double r, const std::string& entity) {
  if (!(r > 0) || !std::isfinite(r)) throw GeometryError(entity, "radius " + std::to_string(r) + " is not positive");
}

// The unit arc from a0 to a1 (clockwise when a1 < a0), its control points mapped by `map`.
template <class Map>
NurbsCurve mapped_unit_arc(double a0, double a1, const std::string& entity, int dimension, Map map) {
  if (a0 == a1) throw GeometryError(entity, "its start and end angles are equal");
  NurbsCurve curve;
  try {
    curve = unit_arc(arc_spans(std::min(a0, a1), std::max(a0, a1)));
  } catch (const GeometryError& error) {
    throw GeometryError(entity, error.reason());
  }
  curve.dimension = dimension;
  for (Eigen::Vector3d& p : curve.points) p = map(p.x(), p.y());  // affine: same knots and weights
  if (a1 > a0) return curve;
  NurbsCurve backwards = reversed(curve);  // its knots a0 + a1 - k: the ends exact again
  std::fill(backwards.knots.begin(), backwards.knots.begin() + 3, a1);
  std::fill(backwards.knots.end() - 3, backwards.knots.end(), a0);
  return backwards;
}

}  // namespace

NurbsCurve line_segment(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double t0, double t1) {
  if (!(t1 > t0) || !std::isfinite(t0) || !std::isfinite(t1))
    throw GeometryError("line segment", "its parameter range [" + std::to_string(t0) + ", " + std::to_string(t1) +
                                            "] is empty or not finite");
  NurbsCurve curve;
  curve.dimension = 3;
  curve.order = 2;
  curve.knots = {t0, t0, t1, t1};
  curve.points = {from, to};
  return curve;
}

NurbsCurve circle_arc(const AxisFrame& frame, double radius, double a0, double a1) {
  check_radius(radius, "circle");
  return mapped_unit_arc(a0, a1, "circle", 3, [&](double c, double s) {
    return Eigen::Vector3d(frame.origin + radius * c * frame.x + radius * s * frame.y);
  });
}

NurbsCurve ellipse_arc(const AxisFrame& frame, double semi_axis_1, double semi_axis_2, double a0, double a1) {
  check_radius(semi_axis_1, "ellipse");
  check_radius(semi_axis_2, "ellipse");
  return mapped_unit_arc(a0, a1, "ellipse", 3, [&](double c, double s) {
    return Eigen::Vector3d(frame.origin + semi_axis_1 * c * frame.x + semi_axis_2 * s * frame.y);
  });
}

NurbsCurve circle_arc_2d(const Eigen::Vector2d& centre, double radius, double a0, double a1) {
  check_radius(radius, "circle");
  return mapped_unit_arc(a0, a1, "circle", 2, [&](double c, double s) {
    return Eigen::Vector3d(centre.x() + radius * c, centre.y() + radius * s, 0.0);
  });
}

}  // namespace cadnurbs
