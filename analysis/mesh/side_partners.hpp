#pragma once
// The sides of an indexed triangle mesh paired across their edges: the adjacency that orient_faces and
// crease_normals walk (which faces meet at an edge, and which way each runs along it).
#include <vector>

#include "core/triangle_mesh.hpp"

namespace cadnurbs {

// Side s = 3t + k is triangle t's side from its corner k to corner (k + 1) % 3.
// Each side's partner across its edge, for the steps that only need edges with exactly two faces.
struct SidePartners {
  std::vector<int> partner;    // side s's: the other side of its edge when the edge has exactly two, else -1
  int boundary_edges = 0;      // edges with one side
  int non_manifold_edges = 0;  // edges with three or more
};

// Takes a mesh whose indices are in range (validate()); returns its sides' partners. Edges are vertex
// pairs, so weld first when positions repeat. O(n) for n triangles, plus a sort of the sides at each vertex
// (a few, except at fan centres: O(k log k) there). The vertices are shared out to worker_threads()
// threads in ranges, each grouping the sides whose lower vertex is in its range; an edge is found whole
// by one thread, so the result does not depend on the thread count.
SidePartners side_partners(const TriangleMesh& mesh);

// The vertex side s runs from.
inline int side_from(const TriangleMesh& mesh, int s) { return mesh.triangles[s / 3][s % 3]; }

}  // namespace cadnurbs
