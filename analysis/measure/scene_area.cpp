#include "analysis/measure/scene_area.hpp"

#include "analysis/measure/trimmed_surface_area.hpp"

namespace cadnurbs {

double shape_area(const Shape& shape, const Eigen::Affine3d& world, double relative_tolerance) {
  if (const auto* t = std::get_if<TrimmedSurface>(&shape.geometry)) {
    TrimmedSurface placed = *t;
    for (auto& p : placed.surface.points) p = world * p;
    return trimmed_surface_area(placed, relative_tolerance);
  }
  TriangleMesh mesh;
  if (const auto* m = std::get_if<TriangleMesh>(&shape.geometry)) mesh = *m;
  else if (const auto* pm = std::get_if<PolygonMesh>(&shape.geometry)) mesh = triangulated(*pm);
  else return 0.0;
  for (auto& p : mesh.positions) p = world * p;
  return mesh_area(mesh);
}

double scene_area(const Scene& scene, double relative_tolerance) {
  double area = 0.0;
  for_each_shape(scene, [&](const Shape& shape, const Eigen::Affine3d& world, const Colour&) {
    area += shape_area(shape, world, relative_tolerance);
  });
  return area;
}

}  // namespace cadnurbs
