#pragma once
// The node of a scene that a reader made from one entity of its file (SceneNode::source_entity, such as "object 3"),
// found depth first from `root`. Readers name each entity once, so the first match is the only one; nullptr when no
// node has that name.
#include <string>

#include "core/scene.hpp"

namespace cadnurbs {

SceneNode* find_scene_node(SceneNode& root, const std::string& source_entity);
const SceneNode* find_scene_node(const SceneNode& root, const std::string& source_entity);

}  // namespace cadnurbs
