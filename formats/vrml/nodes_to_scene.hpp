#pragma once
// A node document back to a Scene (the inverse of scene_to_nodes.hpp), taken at rest: as the file
// states it before any event.
//   - WorldInfo info strings give the unit, the control point convention (it wins over the caller's)
//     and the original names of renamed DEFs (world_info.hpp); without them: millimetres, the caller's
//     convention, DEF names as names.
//   - One top-level grouping node and nothing else is the root node; otherwise an unnamed root holds the
//     top-level shapes and groups.
//   - Grouping nodes -> SceneNode (name from DEF): Transform, and the nodes placed like it (HAnimHumanoid,
//     HAnimJoint, HAnimSite, CADPart, CADAssembly), with their transforms; Group, NurbsGroup, StaticGroup,
//     Anchor, Billboard (as seen from its own axes), Collision, HAnimSegment, CADLayer, CADFace; Switch:
//     its chosen child (whichChoice); LOD: its first, most detailed level; a CoordinateDeformer is a group
//     whose volume (when it has control points) moves its children's coordinates (coordinate_deformer.hpp).
//     A NurbsGroup without DEF (as the writer makes it) gives its shapes to the enclosing node.
//   - PROTO instances are their bodies' first nodes with the instance's field values (proto_expansion.hpp),
//     also for an EXTERNPROTO whose url names a local file that declares it.
//   - Inline (and InlineLoadControl) of a local file: that file's scene, read the same way, as a node (named
//     by the Inline's DEF) where the Inline stands (linked_files.hpp), in the including file's unit and
//     control point convention; a file that cannot be read is a note naming it. `name_for_errors` is taken
//     as the input's path for this: relative urls are resolved in its folder.
//   - Shape -> Shape(s) (nodes_to_geometry.hpp). Material diffuseColor (else emissiveColor;
//     PhysicalMaterial baseColor, UnlitMaterial emissiveColor) is the colour; an Appearance DEF'd
//     "<A>_colour" or "<A>_line_colour" for an enclosing node DEF'd A gives A's colour, which the shape
//     then inherits.
//   - WorldInfo, NavigationInfo, Viewpoint: read, no note (the writers make their own).
//   - Everything else has no place in a Scene and is left out with one note per kind, counted:
//     animation and interaction (interpolators, sensors, Script, ROUTE, also inside PROTO bodies), instances
//     of an EXTERNPROTO no local file declares, geometry without a form here (Text, Cylinder, PointSet...),
//     textures, an Inline whose url is not a local file (or that would include itself, or lies more than
//     kMaxLinkDepth files deep: named by its url), lights and environment, a CoordinateDeformer whose
//     volume is invalid (with its children), a deformer's inputCoord/outputCoord.
//   - A USE'd group or shape is copied; more than a million copies in all is refused.
#include <string>
#include <vector>

#include "core/scene.hpp"
#include "formats/vrml/node_graph.hpp"

namespace cadnurbs {

struct SceneFromNodes {
  Scene scene;
  // One line per kind of node left out, "<count> <kind> left out: <why>", in the order first met.
  std::vector<std::string> notes;
};

// Throws FileError "<name_for_errors>: line N: <reason>" for a node that cannot stand where it is
// (a Material among children...) and for invalid geometry.
SceneFromNodes nodes_to_scene(const NodeDocument& document, const std::string& name_for_errors,
                              bool homogeneous_control_points);

}  // namespace cadnurbs
