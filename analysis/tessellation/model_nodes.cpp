#include "analysis/tessellation/model_nodes.hpp"

namespace cadnurbs::tessellation {

NodeId ModelNodes::add(const Eigen::Vector3d& point, int face) {
  points_.push_back(point);
  faces_of_points_.push_back(face);
  return NodeId{static_cast<int>(points_.size()) - 1};
}

Eigen::Vector3d ModelNodes::in_frame_of(NodeId node, int face) const {
  const Eigen::Affine3d& from = faces_[faces_of_points_[node.index]].world;
  const Eigen::Affine3d& to = faces_[face].world;
  if (from.matrix() == to.matrix()) return points_[node.index];
  return to.inverse() * (from * points_[node.index]);
}

}  // namespace cadnurbs::tessellation
