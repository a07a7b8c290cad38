#pragma once
// A Scene as a VRML97 or X3D node graph (the mapping shared by all three encodings):
//   WorldInfo { title, info (world_info.hpp) }, NavigationInfo { type ["EXAMINE" "ANY"] headlight TRUE },
//   Viewpoint, then the root SceneNode.
// Each SceneNode becomes a Transform (translation, rotation, scale, scaleOrientation from its affine map)
// or a plain Group when its transform is the identity within the written precision; its shapes come
// first among the children, then its child nodes. DEF names come from the names (vrml_identifier.hpp).
// VRML97: when a node has two or more NURBS surfaces, its shapes go into one NurbsGroup (no DEF).
// Each Shape is Shape { appearance Appearance { material Material {...} } geometry ... }:
//   - a shape with its own colour: an Appearance of its own (diffuseColor; emissiveColor for curves,
//     which viewers draw unlit);
//   - a shape inheriting a node's colour: the Appearance "DEF <nodeDEF>_colour" (curves:
//     "<nodeDEF>_line_colour"), written once and USE'd after, which is how a reader finds the node's
//     colour again;
//   - no colour anywhere: Material {} (surfaces, meshes), no Appearance (curves).
// A node colour that no shape inherits has no effect and is not written. Then repeated pieces are written
// once and USE'd (share_repeated_nodes.hpp): equal Appearances, equal shapes, the equal contents of
// instances.
// Precision besides the geometry's: translations within τ (in the parent's units), rotation axes and
// angles within τ/(4R) and scale factors within τ·s/(4R), R the largest distance from the node's origin
// to a corner of the scene's box (first-order estimates); colours within 1/512; the Viewpoint within
// 1e-6 (relative for the position) whatever the scene, so one camera is spelled alike in every file.
#include "core/scene.hpp"
#include "formats/vrml/vrml_write_options.hpp"
#include "formats/vrml/node_graph.hpp"

namespace cadnurbs {

// The node graph for `scene` (expected valid; see core validate). Throws GeometryError naming the node
// whose transform is singular or not finite.
NodeDocument scene_to_nodes(const Scene& scene, const VrmlWriteOptions& options);

// The coordinate tolerance the options stand for: options.coordinate_tolerance, or 1e-6 × the bounding-box
// diagonal of the scene (1e-6 for an empty or point-sized scene).
double effective_coordinate_tolerance(const Scene& scene, const VrmlWriteOptions& options);

}  // namespace cadnurbs
