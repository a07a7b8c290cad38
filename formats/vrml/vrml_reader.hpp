#pragma once
// Reads what the VRML writer writes (VRML97, X3D classic, X3D XML; told apart by content, not by
// extension) back into a Scene, and simple NURBS files of other tools that stay inside the same subset
// (nodes_to_scene.hpp, nodes_to_geometry.hpp, node_schema.hpp). Not a general VRML reader: anything
// outside the subset is refused with the node and line named.
#include <string>

#include "core/scene.hpp"

namespace cadnurbs {

// Scene from the file's bytes: text, or gzip'd text (told apart by content). `homogeneous_control_points`: controlPoint holds w·P (the default and what the
// viewers assume) or P; a cadnurbs "controlPoint ..." WorldInfo line in the file overrides it.
// Throws FileError "<name_for_errors>: line N: <reason>", or "<name_for_errors>: <reason>" for damaged
// gzip data.
Scene parse_vrml(const std::string& bytes, const std::string& name_for_errors, bool homogeneous_control_points = true);

// parse_vrml of the file at `path`; also throws FileError when it cannot be read.
Scene read_vrml(const std::string& path, bool homogeneous_control_points = true);

}  // namespace cadnurbs
