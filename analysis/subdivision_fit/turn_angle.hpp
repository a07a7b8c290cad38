#pragma once
// How far a chain of sharp edges turns at a vertex: the angle between the directions a -> v and v -> b
// (0 = straight on, pi = straight back). Where it reaches the crease angle the vertex is a corner
// (decimate_control_mesh locks it, tag_sharp_edges tags it).
#include <Eigen/Core>
#include <algorithm>
#include <cmath>

namespace cadnurbs {

// 0 when a side has no length: no direction, so no corner.
inline double turn_angle(const Eigen::Vector3d& a, const Eigen::Vector3d& v, const Eigen::Vector3d& b) {
  const Eigen::Vector3d in = v - a, out = b - v;
  if (in.norm() == 0 || out.norm() == 0) return 0;
  return std::acos(std::clamp(in.normalized().dot(out.normalized()), -1.0, 1.0));
}

}  // namespace cadnurbs
