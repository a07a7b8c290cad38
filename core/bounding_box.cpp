#include "core/bounding_box.hpp"

namespace cadnurbs {

Eigen::AlignedBox3d scene_bounding_box(const Scene& scene) {
  Eigen::AlignedBox3d box;
  for_each_shape(scene, [&](const Shape& shape, const Eigen::Affine3d& world, const Colour&) {
    if (const auto* t = std::get_if<TrimmedSurface>(&shape.geometry))
      for (const auto& p : t->surface.points) box.extend(world * p);
    else if (const auto* c = std::get_if<NurbsCurve>(&shape.geometry))
      for (const auto& p : c->points) box.extend(world * p);
    else if (const auto* m = std::get_if<TriangleMesh>(&shape.geometry))
      for (const auto& p : m->positions) box.extend(world * p);
    else if (const auto* pm = std::get_if<PolygonMesh>(&shape.geometry))
      for (const auto& p : pm->positions) box.extend(world * p);
  });
  return box;
}

Eigen::AlignedBox3d mesh_bounding_box(const TriangleMesh& mesh) {
  Eigen::AlignedBox3d box;
  for (const auto& p : mesh.positions) box.extend(p);
  return box;
}

}  // namespace cadnurbs
