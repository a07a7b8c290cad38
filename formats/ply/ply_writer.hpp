#pragma once
// PLY (Stanford polygon file) output of a triangle mesh: binary little-endian, float32 positions,
// optional float32 vertex normals, uint32 triangle indices.
#include <string>

#include "core/triangle_mesh.hpp"

namespace cadnurbs {

// The file bytes. Per-corner normals become per-vertex normals only where every corner of a vertex
// agrees; otherwise the vertex is split so that no normal is lost. Refuses (GeometryError) an
// invalid mesh or coordinates beyond float range.
std::string format_ply(const TriangleMesh& mesh, const std::string& comment);

// format_ply written atomically to `path` (FileError on failure).
void write_ply(const std::string& path, const TriangleMesh& mesh, const std::string& comment);

}  // namespace cadnurbs
