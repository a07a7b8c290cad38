#include "analysis/mesh/scene_triangles.hpp"

namespace cadnurbs {

TriangleMesh scene_triangles(const Scene& scene) {
  TriangleMesh out;
  for_each_shape(scene, [&](const Shape& shape, const Eigen::Affine3d& world, const Colour&) {
    TriangleMesh moved;
    if (const auto* mesh = std::get_if<TriangleMesh>(&shape.geometry)) moved = *mesh;
    else if (const auto* polygons = std::get_if<PolygonMesh>(&shape.geometry)) moved = triangulated(*polygons);
    else return;
    if (!world.matrix().isIdentity(0)) {
      const Eigen::Matrix3d normal_matrix = world.linear().inverse().transpose();
      for (auto& p : moved.positions) p = world * p;
      for (auto& n : moved.corner_normals) n = (normal_matrix * n).normalized();
    }
    append(out, moved);
  });
  return out;
}

std::size_t shape_triangle_count(const Shape& shape) {
  if (const auto* mesh = std::get_if<TriangleMesh>(&shape.geometry)) return mesh->triangles.size();
  if (const auto* polygons = std::get_if<PolygonMesh>(&shape.geometry)) return triangulated_count(*polygons);
  return 0;
}

}  // namespace cadnurbs
