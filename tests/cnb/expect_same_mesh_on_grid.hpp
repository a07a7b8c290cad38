#pragma once
// A decoded .cnb mesh against the mesh written: the same oriented triangles with every corner rounded to
// the grid `step`, and as many vertices (the traversal and copies renumber vertices and reorder triangles).
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/mesh/oriented_triangle_keys.hpp"
#include "core/triangle_mesh.hpp"

namespace cadnurbs {

// `mesh` with every vertex rounded to the grid `step`, as the writer rounds it.
inline TriangleMesh mesh_on_grid(TriangleMesh mesh, double step) {
  for (auto& p : mesh.positions)
    for (int k = 0; k < 3; ++k) p[k] = static_cast<double>(std::llround(p[k] / step)) * step;
  return mesh;
}

inline void expect_same_mesh_on_grid(const TriangleMesh& mesh, const TriangleMesh& decoded, double step) {
  const TriangleMesh on_grid = mesh_on_grid(mesh, step);
  ASSERT_EQ(decoded.triangles.size(), mesh.triangles.size());
  EXPECT_EQ(oriented_triangle_keys(decoded.positions, decoded.triangles),
            oriented_triangle_keys(on_grid.positions, on_grid.triangles));
  EXPECT_EQ(decoded.positions.size(), mesh.positions.size());
}

}  // namespace cadnurbs
