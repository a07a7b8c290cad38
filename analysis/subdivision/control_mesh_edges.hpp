#pragma once
// The edges of a triangle mesh, as Loop's rules need them: for every edge its two ends, its faces'
// opposite vertices, and whether it is sharp. Topology only: no positions.
#include <array>
#include <vector>

#include "core/subdivision_control_mesh.hpp"

namespace cadnurbs {

// How a vertex is refined, from the number of sharp edges at it (crease-tagged or boundary):
// 0 smooth, 1 dart (smooth rules; the crease fades out there), 2 crease (curve rules), 3 or more, or
// tagged, corner (stays where it is). Hoppe et al. 1994, section 3.2.
enum class ControlVertexKind { smooth, dart, crease, corner };

// The connectivity of one subdivision level (the control mesh's, or a refined one's).
struct ControlMeshTopology {
  int vertex_count = 0;
  std::vector<std::array<int, 3>> triangles;
  std::vector<std::array<int, 2>> crease_edges;  // tagged sharp, {a < b}
  std::vector<int> corner_vertices;              // tagged corners
};

struct ControlMeshEdges {
  std::vector<std::array<int, 2>> ends;            // {a < b}
  std::vector<std::array<int, 2>> opposite;        // the third vertex of its first two faces (-1: none)
  std::vector<int> face_count;                     // 1 boundary, 2 interior, 3+ non-manifold
  std::vector<char> sharp;                         // tagged, boundary or non-manifold
  std::vector<std::array<int, 3>> triangle_edges;  // edge k of triangle t joins corners k and k+1
  std::vector<std::vector<int>> vertex_edges;      // the edges at each vertex
  std::vector<ControlVertexKind> vertex_kind;
};

// The topology of a control mesh (its positions left out).
ControlMeshTopology control_mesh_topology(const SubdivisionControlMesh& mesh);

// Takes a level's topology; returns its edges, in order of first appearance (triangle by triangle).
// Vertex kinds follow Hoppe et al. 1994: the number of sharp edges at a vertex decides (0 smooth,
// 1 dart, 2 crease, 3+ corner); a tagged corner is a corner whatever its edges. A vertex no triangle
// uses is a corner (it has nothing to be smoothed with).
// Refuses (std::invalid_argument) an index out of range, a triangle with a repeated vertex, and a
// crease tag on a pair that is not an edge.
ControlMeshEdges control_mesh_edges(const ControlMeshTopology& level);

// The other end of edge `e` seen from vertex `v`.
inline int other_end(const ControlMeshEdges& edges, int e, int v) {
  return edges.ends[e][0] == v ? edges.ends[e][1] : edges.ends[e][0];
}

}  // namespace cadnurbs
