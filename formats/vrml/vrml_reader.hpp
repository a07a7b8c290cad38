#pragma once
// Reads VRML97 and X3D files (classic or XML encoding; told apart by content, not by extension) into a
// Scene: whole scene graphs of any node of the standards (node_schema.hpp), PROTO and EXTERNPROTO
// instances, Scripts and ROUTEs, taken at rest (nodes_to_scene.hpp says what becomes what, and what is
// left out with a note per kind); the geometry as nodes_to_geometry.hpp reads it.
#include <string>

#include "core/scene.hpp"
#include "formats/vrml/node_graph.hpp"
#include "formats/vrml/nodes_to_scene.hpp"

namespace cadnurbs {

// Scene from the file's bytes: text, or gzip'd text (told apart by content). `homogeneous_control_points`: controlPoint holds w·P (the default and what the
// viewers assume) or P; a cadnurbs "controlPoint ..." WorldInfo line in the file overrides it.
// Throws FileError "<name_for_errors>: line N: <reason>", or "<name_for_errors>: <reason>" for damaged
// gzip data.
Scene parse_vrml(const std::string& bytes, const std::string& name_for_errors, bool homogeneous_control_points = true);

// The file's node document (no Scene): text or gzip'd text, classic or XML, told apart by content.
NodeDocument parse_vrml_document(const std::string& bytes, const std::string& name_for_errors);

// parse_vrml with the notes of what was left out (SceneFromNodes::notes).
SceneFromNodes parse_vrml_scene(const std::string& bytes, const std::string& name_for_errors,
                                bool homogeneous_control_points = true);

// parse_vrml of the file at `path`; also throws FileError when it cannot be read.
Scene read_vrml(const std::string& path, bool homogeneous_control_points = true);
SceneFromNodes read_vrml_scene(const std::string& path, bool homogeneous_control_points = true);

}  // namespace cadnurbs
