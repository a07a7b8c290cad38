#pragma once
// The control mesh of a Loop subdivision surface with sharp features (Hoppe et al. 1994): triangles,
// and the edges and vertices tagged sharp. Topology only says where the rules change; the rules
// themselves are in loop_refinement and loop_limit_stencils.
#include <array>
#include <vector>

#include "core/triangle_mesh.hpp"

namespace cadnurbs {

struct LoopControlMesh {
  std::vector<Eigen::Vector3d> positions;
  std::vector<std::array<int, 3>> triangles;   // counter-clockwise seen from outside
  std::vector<std::array<int, 2>> crease_edges;  // tagged sharp; each {a, b} with a < b, an edge of a triangle
  std::vector<int> corner_vertices;             // tagged corners (interpolated, no smoothing)
};

// How a vertex is refined, from the number of sharp edges at it (crease-tagged or boundary):
// 0 smooth, 1 dart (smooth rules; the crease fades out there), 2 crease (curve rules), 3 or more, or
// tagged, corner (stays where it is). Hoppe et al. 1994, section 3.2.
enum class LoopVertexKind { smooth, dart, crease, corner };

}  // namespace cadnurbs
