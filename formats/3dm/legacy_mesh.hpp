#pragma once
// Rhino 1's meshes (TCODE_MESH_OBJECT) as TriangleMesh, as openNURBS's ReadV1_TCODE_MESH_OBJECT makes an ON_Mesh of
// them (facts from opennurbs_archive.cpp).
//
// Layout: the object chunk holds a TCODE_COMPRESSED_MESH_GEOMETRY chunk, then the object's attribute chunks. The
// geometry chunk (integers int32): vertex count (> 0), face count (> 0), has-normals and has-texture-coordinates flags,
// the bounding box (2 points of 3 doubles), then
//   vertices: 3 uint16 each, a fraction of the box (x = min.x + q * (max.x - min.x) / 65535);
//   faces: 4 indices each (mesh_faces.hpp), uint16 when the vertex count is below 65535, else int32;
//   normals (when flagged): 3 int8 each, a component being q / 127;
//   texture coordinates (when flagged): 2 uint16 each, read past.
// So a vertex is within half a step (box size / 131070 on each axis) of the one Rhino 1 meshed: the quantisation is
// the file's, not this reader's.
//
// Throws ArchiveError ("... V1 mesh: <reason>") on a count that is not positive or whose arrays cannot fit in the chunk
// (checked before allocating), on a face index outside the vertices, and on a box that is not finite.
#include "core/triangle_mesh.hpp"
#include "formats/3dm/archive_reader.hpp"

namespace cadnurbs::rhino {

// The reader is inside the TCODE_COMPRESSED_MESH_GEOMETRY chunk.
TriangleMesh read_legacy_mesh(ArchiveReader& reader);

}  // namespace cadnurbs::rhino
