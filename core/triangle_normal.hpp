#pragma once
// The unit normal of a triangle: what crease normals and the Loop fit's closest points both measure with.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace cadnurbs {

// Takes the corners a, b, c (counter-clockwise seen from the side the normal points to); returns the
// unit normal, or zero when the triangle has no area.
inline Eigen::Vector3d unit_normal(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double length = n.norm();
  return length > 0 ? Eigen::Vector3d(n / length) : Eigen::Vector3d::Zero();
}

}  // namespace cadnurbs
