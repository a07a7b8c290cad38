#pragma once
// Wavefront OBJ output of a triangle mesh: "v x y z" lines, "vn" lines for distinct corner normals,
// "f a b c" (or "f a//n b//n c//n") with 1-based indices. Text, shortest round-trip numbers.
#include <string>

#include "core/triangle_mesh.hpp"

namespace cadnurbs {

// The file text, with `comment` on a first "#" line (line breaks in it become spaces). Refuses
// (GeometryError) an invalid mesh.
std::string format_obj(const TriangleMesh& mesh, const std::string& comment);

// format_obj written atomically to `path` (FileError on failure).
void write_obj(const std::string& path, const TriangleMesh& mesh, const std::string& comment);

}  // namespace cadnurbs
