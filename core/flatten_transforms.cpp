#include "core/flatten_transforms.hpp"

namespace cadnurbs {

namespace {

void map_points(std::vector<Eigen::Vector3d>& points, const Eigen::Affine3d& world) {
  for (auto& p : points) p = world * p;
}

struct MapGeometry {
  const Eigen::Affine3d& world;
  void operator()(TrimmedSurface& t) const { map_points(t.surface.points, world); }
  void operator()(NurbsCurve& c) const {
    if (c.dimension == 3) map_points(c.points, world);
  }
  void operator()(PolygonMesh& m) const { map_points(m.positions, world); }
  void operator()(TriangleMesh& m) const {
    map_points(m.positions, world);
    const Eigen::Matrix3d normal_map = world.linear().inverse().transpose();
    for (auto& n : m.corner_normals) {
      const Eigen::Vector3d mapped = normal_map * n;
      if (mapped.norm() > 0) n = mapped.normalized();
    }
  }
};

void flatten(SceneNode& node, const Eigen::Affine3d& parent) {
  const Eigen::Affine3d world = parent * node.transform;
  node.transform = Eigen::Affine3d::Identity();
  if (world.matrix() != Eigen::Matrix4d::Identity())
    for (auto& shape : node.shapes) std::visit(MapGeometry{world}, shape.geometry);
  for (auto& child : node.children) flatten(child, world);
}

}  // namespace

Scene flatten_transforms(const Scene& scene) {
  Scene out = scene;
  flatten(out.root, Eigen::Affine3d::Identity());
  return out;
}

}  // namespace cadnurbs
