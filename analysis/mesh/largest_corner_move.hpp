#pragma once
// How far a mesh moved on its way through a file: the written mesh and the mesh read back, compared
// corner by corner. Mesh writers keep the order of triangles and of their corners and only round the
// coordinates, so the comparison is exact where it applies; and since every point of a triangle is the
// same barycentric combination of its corners before and after, no point of the mesh moved farther than
// the largest corner did. That is what makes "certificate + largest corner move" a bound of the file.
#include <optional>

#include "core/triangle_mesh.hpp"

namespace cadnurbs {

// The largest distance between corner k of triangle t of `written` and of `read_back`, over every t and
// k; nullopt when the two meshes do not have the same number of triangles (the file did not keep them,
// so they cannot be paired).
std::optional<double> largest_corner_move(const TriangleMesh& written, const TriangleMesh& read_back);

}  // namespace cadnurbs
