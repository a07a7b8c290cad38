#include "core/world_scale.hpp"

#include <Eigen/SVD>
#include <algorithm>

namespace cadnurbs {

double transform_scale(const Eigen::Affine3d& transform) {
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(transform.linear());
  return svd.singularValues()(0);
}

namespace {
void largest_scale(const SceneNode& node, const Eigen::Affine3d& parent, double& largest) {
  const Eigen::Affine3d world = parent * node.transform;
  if (!node.shapes.empty()) largest = std::max(largest, transform_scale(world));
  for (const auto& child : node.children) largest_scale(child, world, largest);
}
}  // namespace

double largest_world_scale(const Scene& scene) {
  double largest = 0.0;
  largest_scale(scene.root, Eigen::Affine3d::Identity(), largest);
  return largest > 0.0 ? largest : 1.0;
}

}  // namespace cadnurbs
