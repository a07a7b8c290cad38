#include "analysis/mesh/merge_world_meshes.hpp"

#include <variant>
#include <vector>

#include "analysis/mesh/weld_exact.hpp"

namespace cadnurbs {

namespace {

// The node without its triangle meshes; false when nothing is left of it.
bool without_meshes(const SceneNode& node, SceneNode& out) {
  out.name = node.name;
  out.source_entity = node.source_entity;
  out.transform = node.transform;
  out.colour = node.colour;
  for (const auto& shape : node.shapes)
    if (!std::holds_alternative<TriangleMesh>(shape.geometry)) out.shapes.push_back(shape);
  for (const auto& child : node.children) {
    SceneNode kept;
    if (without_meshes(child, kept)) out.children.push_back(std::move(kept));
  }
  return !out.shapes.empty() || !out.children.empty();
}

}  // namespace

Scene merge_world_meshes(const Scene& scene) {
  std::vector<Colour> colours;
  std::vector<TriangleMesh> merged;
  for_each_shape(scene, [&](const Shape& shape, const Eigen::Affine3d& world, const Colour& colour) {
    const auto* mesh = std::get_if<TriangleMesh>(&shape.geometry);
    if (!mesh) return;
    size_t k = 0;
    while (k < colours.size() && !(colours[k] == colour)) ++k;
    if (k == colours.size()) {
      colours.push_back(colour);
      merged.emplace_back();
    }
    TriangleMesh placed;
    placed.triangles = mesh->triangles;
    for (const auto& p : mesh->positions) placed.positions.push_back(world * p);
    append(merged[k], placed);
  });
  Scene out;
  out.unit = scene.unit;
  out.source_unit = scene.source_unit;
  without_meshes(scene.root, out.root);
  std::vector<Shape> meshes;
  for (size_t k = 0; k < merged.size(); ++k) {
    TriangleMesh welded = weld_exact(merged[k]);
    welded.corner_normals.clear();
    meshes.push_back({"meshes", std::move(welded), colours[k]});
  }
  out.root.shapes.insert(out.root.shapes.begin(), meshes.begin(), meshes.end());
  return out;
}

}  // namespace cadnurbs
