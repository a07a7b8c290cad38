#pragma once
// The units a coding is chosen for: "bodies", sets of scene nodes whose shapes must be coded the same way
// so that the decoded part stays watertight. A node's shapes are one body; two nodes are one body when a
// trimming segment of one and a trimming segment of the other lie on the same model edge (TrimEdgeRef
// edge number), since a meshed face next to a NURBS face would crack along that edge.
#include <Eigen/Geometry>
#include <vector>

#include "core/scene.hpp"

namespace cadnurbs {

struct SceneBodies {
  // Every node of the tree in depth-first pre-order (the root first), with its world transform and the
  // colour its shapes inherit. nodes_in_order of a copy of the scene lists the copy's nodes in this order.
  std::vector<const SceneNode*> nodes;
  std::vector<Eigen::Affine3d> world;
  std::vector<Colour> colour;
  // Each body's node indices (into `nodes`), increasing; bodies ordered by their first node. Nodes
  // without shapes belong to no body.
  std::vector<std::vector<int>> bodies;
};

SceneBodies scene_bodies(const Scene& scene);

// The nodes under `root` (itself first) in the depth-first pre-order of SceneBodies::nodes.
std::vector<SceneNode*> nodes_in_order(SceneNode& root);

// A scene holding only `body`'s nodes, each a child of an empty root (named and unit as `scene`) at its
// world placement with its inherited colour, holding `shapes[k]` for the body's k-th node (or, with
// `shapes` empty, that node's own shapes). Children of the nodes are not taken.
Scene body_scene(const Scene& scene, const SceneBodies& bodies, int body,
                 const std::vector<std::vector<Shape>>& shapes = {});

}  // namespace cadnurbs
