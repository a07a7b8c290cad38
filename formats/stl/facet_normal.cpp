#include "formats/stl/facet_normal.hpp"

#include <Eigen/Geometry>

namespace cadnurbs {

Eigen::Vector3d facet_normal(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double length = n.norm();
  if (!(length > 0.0) || !std::isfinite(length)) return Eigen::Vector3d::Zero();
  return n / length;
}

}  // namespace cadnurbs
