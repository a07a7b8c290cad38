#include "formats/vrml/viewpoint.hpp"

#include <cmath>

namespace cadnurbs {

Viewpoint framing_viewpoint(const Eigen::AlignedBox3d& box, double field_of_view) {
  Viewpoint view;
  view.field_of_view = field_of_view;
  if (box.isEmpty()) return view;
  const Eigen::Vector3d centre = box.center();
  double radius = 0.5 * box.diagonal().norm();
  if (!(radius > 0.0)) radius = 1.0;
  const double distance = radius / std::sin(0.5 * field_of_view);
  const Eigen::Vector3d towards_camera = Eigen::Vector3d(1, 1, 1).normalized();
  view.position = centre + distance * towards_camera;
  // Camera frame: it looks along -Z and has +Y up, so the rotation takes Z to -forward and Y to the
  // world up projected off the view direction (no roll).
  const Eigen::Vector3d forward = -towards_camera;
  const Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitY()).normalized();
  const Eigen::Vector3d up = right.cross(forward);
  Eigen::Matrix3d rotation;
  rotation.col(0) = right;
  rotation.col(1) = up;
  rotation.col(2) = -forward;
  view.orientation = Eigen::AngleAxisd(rotation);
  return view;
}

}  // namespace cadnurbs
