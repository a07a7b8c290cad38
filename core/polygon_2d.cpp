#include "core/polygon_2d.hpp"

namespace cadnurbs {

double polygon_signed_area(const std::vector<Eigen::Vector2d>& polygon) {
  double twice = 0.0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % polygon.size()];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * twice;
}

bool convex_corner(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c, double tolerance) {
  const Eigen::Vector2d ab = b - a, bc = c - b;
  const double length = (c - a).norm();
  const double cross = ab.x() * bc.y() - ab.y() * bc.x();
  return length == 0.0 || cross / length >= -tolerance;
}

}  // namespace cadnurbs
