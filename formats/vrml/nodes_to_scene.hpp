#pragma once
// A node document back to a Scene (the inverse of scene_to_nodes.hpp):
//   - WorldInfo info strings give the unit, the control point convention (it wins over the caller's)
//     and the original names of renamed DEFs (world_info.hpp); without them: millimetres, the caller's
//     convention, DEF names as names.
//   - One top-level Transform/Group/NurbsGroup and nothing else is the root node; otherwise an unnamed
//     root holds the top-level shapes and groups.
//   - Transform/Group/NurbsGroup -> SceneNode (name from DEF), Shape -> Shape(s) (nodes_to_geometry.hpp);
//     a NurbsGroup without DEF (as the writer makes it) gives its shapes to the enclosing node.
//   - Material diffuseColor (else emissiveColor) is the colour; an Appearance DEF'd "<A>_colour" or
//     "<A>_line_colour" for an enclosing node DEF'd A gives A's colour, which the shape then inherits.
//   - NavigationInfo and Viewpoint are read and ignored; a Shape without geometry is skipped.
//   - A USE'd group or shape is copied; more than a million copies in all is refused.
#include <string>

#include "core/scene.hpp"
#include "formats/vrml/node_graph.hpp"

namespace cadnurbs {

// Throws FileError "<name_for_errors>: line N: <reason>" for a node that cannot stand where it is
// (a Material among children...) and for invalid geometry.
Scene nodes_to_scene(const NodeDocument& document, const std::string& name_for_errors, bool homogeneous_control_points);

}  // namespace cadnurbs
