#pragma once
// The control mesh of a Loop subdivision surface with sharp features (Hoppe et al. 1994): triangles,
// and the edges and vertices tagged sharp. The tags only say where the rules change; the rules are
// in analysis/subdivision. In core because formats/obj reads and writes it too.
#include <array>
#include <vector>

#include "core/triangle_mesh.hpp"

namespace cadnurbs {

struct SubdivisionControlMesh {
  std::vector<Eigen::Vector3d> positions;
  std::vector<std::array<int, 3>> triangles;   // counter-clockwise seen from outside
  std::vector<std::array<int, 2>> crease_edges;  // tagged sharp; each {a, b} with a < b, an edge of a triangle
  std::vector<int> corner_vertices;             // tagged corners (interpolated, no smoothing)
};

}  // namespace cadnurbs
