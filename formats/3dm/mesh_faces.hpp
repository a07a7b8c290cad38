#pragma once
// The faces and vertex normals of a Rhino mesh, as a TriangleMesh holds them. Rhino stores every face as four vertex
// indices: a quad has four distinct corners, a triangle repeats its third (vi[2] == vi[3]). Shared by ON_Mesh
// (mesh_object.hpp) and Rhino 1's compressed mesh (legacy_mesh.hpp), which store the same faces with different index
// sizes. Facts from openNURBS's ON_MeshFace and ReadV1_TCODE_MESH_OBJECT.
#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "formats/3dm/archive_reader.hpp"

namespace cadnurbs::rhino {

// Reads `face_count` faces of four indices of `index_size` bytes each (1, 2 or 4) and splits quads into two triangles
// (0 1 2, 0 2 3). Throws ArchiveError ("<entity>: <reason>") on another index size, when the faces cannot fit in what
// is left of the chunk (checked before allocating), and on an index not below `vertex_count`.
std::vector<std::array<int, 3>> read_mesh_faces(ArchiveReader& reader, std::size_t face_count, std::size_t vertex_count,
                                                int index_size, const std::string& entity);

// Rhino's normals are per vertex, a TriangleMesh's per triangle corner (3 per triangle, in order). One unusable normal
// (zero or not finite) gives none at all, so that no writer meets a normal it cannot normalise.
std::vector<Eigen::Vector3d> vertex_to_corner_normals(const std::vector<Eigen::Vector3d>& vertex_normals,
                                                      const std::vector<std::array<int, 3>>& triangles);

}  // namespace cadnurbs::rhino
