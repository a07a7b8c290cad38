#include "core/axis_frame.hpp"

#include <cmath>

#include "core/geometry_error.hpp"

namespace cadnurbs {

AxisFrame axis_frame(const Eigen::Vector3d& origin, const std::optional<Eigen::Vector3d>& axis,
                     const std::optional<Eigen::Vector3d>& ref_direction, const std::string& entity) {
  if (!origin.allFinite()) throw GeometryError(entity, "the placement's location is not finite");
  AxisFrame frame;
  frame.origin = origin;
  if (axis) {
    const double length = axis->norm();
    if (!std::isfinite(length) || length == 0.0)
      throw GeometryError(entity, "the placement's axis is zero or not finite");
    frame.z = *axis / length;
  }
  Eigen::Vector3d ref;
  if (ref_direction) {
    ref = *ref_direction;
    const double length = ref.norm();
    if (!std::isfinite(length) || length == 0.0)
      throw GeometryError(entity, "the placement's ref_direction is zero or not finite");
    ref /= length;
  } else {
    // first_proj_axis: (1,0,0) unless the axis lies along it.
    ref = std::abs(frame.z.x()) >= 1.0 - 1e-12 ? Eigen::Vector3d(0, 1, 0) : Eigen::Vector3d(1, 0, 0);
  }
  const Eigen::Vector3d orthogonal = ref - ref.dot(frame.z) * frame.z;
  const double length = orthogonal.norm();
  if (!(length > 1e-12)) throw GeometryError(entity, "the placement's ref_direction is parallel to its axis");
  frame.x = orthogonal / length;
  frame.y = frame.z.cross(frame.x);
  return frame;
}

Eigen::Vector3d to_world(const AxisFrame& frame, const Eigen::Vector3d& local) {
  return frame.origin + local.x() * frame.x + local.y() * frame.y + local.z() * frame.z;
}

Eigen::Vector3d to_local(const AxisFrame& frame, const Eigen::Vector3d& world) {
  const Eigen::Vector3d d = world - frame.origin;
  return {d.dot(frame.x), d.dot(frame.y), d.dot(frame.z)};
}

}  // namespace cadnurbs
