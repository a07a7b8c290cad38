#include "core/scene.hpp"

namespace cadnurbs {

namespace {

void validate_node(const SceneNode& node, const std::string& path) {
  for (size_t i = 0; i < node.shapes.size(); ++i) {
    const auto& shape = node.shapes[i];
    const std::string entity =
        path + "/" + (display_name(shape).empty() ? "shape " + std::to_string(i) : display_name(shape));
    std::visit([&](const auto& g) { validate(g, entity); }, shape.geometry);
  }
  for (size_t i = 0; i < node.children.size(); ++i) {
    const auto& child = node.children[i];
    validate_node(child, path + "/" + (display_name(child).empty() ? "node " + std::to_string(i) : display_name(child)));
  }
}

}  // namespace

void validate(const Scene& scene) {
  validate_node(scene.root, display_name(scene.root).empty() ? "scene" : display_name(scene.root));
}

SceneCounts count_entities(const Scene& scene) {
  SceneCounts c;
  for_each_shape(scene, [&](const Shape& shape, const Eigen::Affine3d&, const Colour&) {
    if (const auto* t = std::get_if<TrimmedSurface>(&shape.geometry)) {
      ++c.surfaces;
      if (!t->loops.empty()) ++c.trimmed_surfaces;
      c.control_points += static_cast<long>(t->surface.points.size());
      c.knots += static_cast<long>(t->surface.u_knots.size() + t->surface.v_knots.size());
      c.trim_loops += static_cast<long>(t->loops.size());
      for (const auto& loop : t->loops)
        for (const auto& seg : loop.segments) {
          if (const auto* curve = std::get_if<NurbsCurve>(&seg)) {
            c.trim_control_points += curve->count();
            c.trim_knots += static_cast<long>(curve->knots.size());
          } else {
            c.trim_control_points += static_cast<long>(std::get<Polyline2D>(seg).points.size());
          }
        }
    } else if (const auto* curve = std::get_if<NurbsCurve>(&shape.geometry)) {
      ++c.curves;
      c.control_points += curve->count();
      c.knots += static_cast<long>(curve->knots.size());
    } else if (const auto* mesh = std::get_if<TriangleMesh>(&shape.geometry)) {
      ++c.meshes;
      c.mesh_vertices += static_cast<long>(mesh->positions.size());
      c.mesh_triangles += static_cast<long>(mesh->triangles.size());
    } else if (const auto* polygons = std::get_if<PolygonMesh>(&shape.geometry)) {
      ++c.polygon_meshes;
      c.polygons += static_cast<long>(polygons->polygons.size());
      c.polygon_vertices += static_cast<long>(polygons->positions.size());
    }
  });
  return c;
}

}  // namespace cadnurbs
