#pragma once
// Rhino's ON_Mesh as a TriangleMesh: its vertices (the double-precision copy when the file has a valid
// one, else the single-precision floats), its faces, quads split into two triangles (0 1 2, 0 2 3), and
// its vertex normals as corner normals when it has them (all finite and non-zero; otherwise none).
// Texture coordinates, curvatures, colours and n-gons are read past, not kept.
#include "core/triangle_mesh.hpp"
#include "formats/3dm/archive_reader.hpp"

namespace cadnurbs::rhino {

// Reads an ON_Mesh's class data (the reader is inside its TCODE_OPENNURBS_CLASS_DATA chunk): chunk
// versions 1.x (plain arrays) and 3.x (compressed arrays, inflated with zlib). Throws ArchiveError
// ("... ON_Mesh: <reason>") on another version, a face index size other than 1, 2 or 4, a face vertex
// index outside the vertex count, and on counts or compressed sizes that do not fit the chunk (checked
// before allocating: a face array must fit in what is left of the chunk, a vertex buffer's declared size
// must equal vertex count * 12 and be reachable from its compressed bytes).
TriangleMesh read_mesh(ArchiveReader& reader);

}  // namespace cadnurbs::rhino
