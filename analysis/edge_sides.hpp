#pragma once
// The sides of an indexed triangle mesh grouped by undirected edge: the adjacency that orient_faces and
// with_crease_normals walk (which faces meet at an edge, and which way each runs along it).
#include <cstddef>
#include <vector>

#include "core/triangle_mesh.hpp"

namespace cadnurbs {

// Side s = 3t + k is triangle t's side from its corner k to corner (k + 1) % 3.
struct EdgeSides {
  std::vector<int> first;  // edge e's sides are sides[first[e]] .. sides[first[e + 1] - 1]
  std::vector<int> sides;  // every side once
  std::size_t edge_count() const { return first.empty() ? 0 : first.size() - 1; }
};

// Takes a mesh whose indices are in range (validate()); returns its sides grouped by vertex pair, edges in
// order of (lower vertex, higher vertex), the sides of an edge in increasing order of s. Edges are vertex
// pairs, so weld first when positions repeat. O(n) for n triangles, plus a sort of the sides at each
// vertex (a few, except at fan centres: O(k log k) there).
EdgeSides edge_sides(const TriangleMesh& mesh);

// Each side's partner across its edge, for the steps that only need edges with exactly two faces.
struct SidePartners {
  std::vector<int> partner;    // side s's: the other side of its edge when the edge has exactly two, else -1
  int boundary_edges = 0;      // edges with one side
  int non_manifold_edges = 0;  // edges with three or more
};

// Takes a mesh as edge_sides does; returns its sides' partners. O(n), as edge_sides.
SidePartners side_partners(const TriangleMesh& mesh);

// The vertices side s runs from and to.
inline int side_from(const TriangleMesh& mesh, int s) { return mesh.triangles[s / 3][s % 3]; }
inline int side_to(const TriangleMesh& mesh, int s) { return mesh.triangles[s / 3][(s % 3 + 1) % 3]; }

}  // namespace cadnurbs
