#include "analysis/coding_choice/scene_bodies.hpp"

#include <map>

#include "core/union_find.hpp"

namespace cadnurbs {

namespace {

void collect(const SceneNode& node, const Eigen::Affine3d& parent, const Colour& inherited, SceneBodies& out) {
  const Eigen::Affine3d world = parent * node.transform;
  const Colour colour = node.colour.value_or(inherited);
  out.nodes.push_back(&node);
  out.world.push_back(world);
  out.colour.push_back(colour);
  for (const auto& child : node.children) collect(child, world, colour, out);
}

void collect_mutable(SceneNode& node, std::vector<SceneNode*>& out) {
  out.push_back(&node);
  for (auto& child : node.children) collect_mutable(child, out);
}

}  // namespace

SceneBodies scene_bodies(const Scene& scene) {
  SceneBodies out;
  collect(scene.root, Eigen::Affine3d::Identity(), Colour{}, out);
  const int n = static_cast<int>(out.nodes.size());
  UnionFind classes(static_cast<size_t>(n));
  std::map<int, int> first_node_of_edge;
  for (int i = 0; i < n; ++i)
    for (const auto& shape : out.nodes[i]->shapes)
      if (const auto* trimmed = std::get_if<TrimmedSurface>(&shape.geometry))
        for (const auto& loop : trimmed->loops)
          for (const auto& ref : loop.edges)
            if (ref.edge >= 0) classes.unite(i, first_node_of_edge.try_emplace(ref.edge, i).first->second);
  std::map<int, int> body_of_root;
  for (int i = 0; i < n; ++i) {
    if (out.nodes[i]->shapes.empty()) continue;
    const auto [it, added] = body_of_root.try_emplace(classes.find(i), static_cast<int>(out.bodies.size()));
    if (added) out.bodies.emplace_back();
    out.bodies[it->second].push_back(i);
  }
  return out;
}

std::vector<SceneNode*> nodes_in_order(SceneNode& root) {
  std::vector<SceneNode*> out;
  collect_mutable(root, out);
  return out;
}

Scene body_scene(const Scene& scene, const SceneBodies& bodies, int body,
                 const std::vector<std::vector<Shape>>& shapes) {
  Scene out;
  out.unit = scene.unit;
  out.source_unit = scene.source_unit;
  out.root.name = scene.root.name;
  const auto& members = bodies.bodies[body];
  for (size_t k = 0; k < members.size(); ++k) {
    const int i = members[k];
    SceneNode node;
    node.name = bodies.nodes[i]->name;
    node.source_entity = bodies.nodes[i]->source_entity;
    node.transform = bodies.world[i];
    node.colour = bodies.colour[i];
    node.shapes = shapes.empty() ? bodies.nodes[i]->shapes : shapes[k];
    out.root.children.push_back(std::move(node));
  }
  return out;
}

}  // namespace cadnurbs
