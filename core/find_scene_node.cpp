#include "core/find_scene_node.hpp"

namespace cadnurbs {

const SceneNode* find_scene_node(const SceneNode& root, const std::string& source_entity) {
  if (root.source_entity == source_entity) return &root;
  for (const auto& child : root.children)
    if (const SceneNode* found = find_scene_node(child, source_entity)) return found;
  return nullptr;
}

SceneNode* find_scene_node(SceneNode& root, const std::string& source_entity) {
  return const_cast<SceneNode*>(find_scene_node(static_cast<const SceneNode&>(root), source_entity));
}

}  // namespace cadnurbs
