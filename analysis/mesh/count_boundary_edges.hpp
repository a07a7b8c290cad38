#pragma once
// Edge topology of a triangle mesh: how many edges have one triangle (boundary) and how many more
// than two (non-manifold). A closed, manifold surface has neither. Edges are identified by vertex
// index, so weld first (weld_exact) when the mesh has repeated positions.
#include "core/triangle_mesh.hpp"

namespace cadnurbs {

struct EdgeCounts {
  long boundary = 0;      // edges used by exactly one triangle
  long non_manifold = 0;  // edges used by three or more triangles
  double boundary_length = 0;  // total length of the boundary edges
};

EdgeCounts count_boundary_edges(const TriangleMesh& mesh);

}  // namespace cadnurbs
