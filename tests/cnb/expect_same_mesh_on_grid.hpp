#pragma once
// A decoded .cnb mesh against the mesh written: the same oriented triangles with every corner rounded to
// the grid `step`, and as many vertices (the traversal and copies renumber vertices and reorder triangles).
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/mesh/oriented_triangle_keys.hpp"
#include "core/triangle_mesh.hpp"

namespace cadnurbs {

inline void expect_same_mesh_on_grid(const TriangleMesh& mesh, const TriangleMesh& decoded, double step) {
  std::vector<Eigen::Vector3d> on_grid;
  for (const auto& p : mesh.positions)
    on_grid.emplace_back(std::llround(p.x() / step) * step, std::llround(p.y() / step) * step,
                         std::llround(p.z() / step) * step);
  ASSERT_EQ(decoded.triangles.size(), mesh.triangles.size());
  EXPECT_EQ(oriented_triangle_keys(decoded.positions, decoded.triangles), oriented_triangle_keys(on_grid, mesh.triangles));
  EXPECT_EQ(decoded.positions.size(), mesh.positions.size());
}

}  // namespace cadnurbs
