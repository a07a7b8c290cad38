// split_t_junctions: a unit square meshed as two halves that meet with a T-junction, and a triangle
// with T-junctions on two edges; after the split the mesh is closed where the halves meet, its area is
// unchanged and no triangle has lost its area.
#include "analysis/mesh/split_t_junctions.hpp"

#include <gtest/gtest.h>

#include "analysis/mesh/count_boundary_edges.hpp"

namespace cadnurbs {
namespace {

double area(const TriangleMesh& m) {
  double total = 0;
  for (const auto& t : m.triangles)
    total += 0.5 * (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]).norm();
  return total;
}

double smallest_area(const TriangleMesh& m) {
  double smallest = 1e300;
  for (const auto& t : m.triangles)
    smallest = std::min(
        smallest, 0.5 * (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]).norm());
  return smallest;
}

TEST(SplitTJunctions, SquareHalvesMeetingAtAMidpointCloseUp) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {0.5, 0, 0}, {0.5, 1, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}, {0.5, 0.5, 0}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 4, 6}, {4, 5, 6}, {5, 2, 6}};
  ASSERT_EQ(count_boundary_edges(m).boundary, 9);
  long splits = 0;
  const TriangleMesh out = split_t_junctions(m, 1e-12, &splits);
  EXPECT_EQ(splits, 1);
  EXPECT_EQ(count_boundary_edges(out).boundary, 6);  // the square's own sides only
  EXPECT_EQ(out.triangles.size(), 6u);
  EXPECT_NEAR(area(out), 1.0, 1e-15);
  EXPECT_GT(smallest_area(out), 0.1);
}

TEST(SplitTJunctions, TwoEdgesSplitFanFromTheCentroid) {
  TriangleMesh m;
  // A big triangle with a T-vertex on its bottom edge (from two triangles below) and on its left edge
  // (from two on the left).
  m.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 0, 0}, {1, -1, 0}, {0, 1, 0}, {-1, 1, 0}};
  m.triangles = {{0, 1, 2}, {0, 3, 4}, {3, 1, 4}, {2, 5, 6}, {5, 0, 6}};
  const double before = area(m);
  long splits = 0;
  const TriangleMesh out = split_t_junctions(m, 1e-12, &splits);
  EXPECT_EQ(splits, 2);
  EXPECT_EQ(out.positions.size(), m.positions.size() + 1);  // the centroid
  EXPECT_NEAR(area(out), before, 1e-14);
  EXPECT_GT(smallest_area(out), 0.1);
  // Only the outer sides are boundary: 4 below and on the left, and the big triangle's hypotenuse.
  EXPECT_EQ(count_boundary_edges(out).boundary, 5);
}

TEST(SplitTJunctions, AVertexOffTheEdgeBeyondTheToleranceIsLeft) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {0.5, 0, 0}, {0.5, 1, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}, {0.5 + 1e-6, 0.5, 0}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 4, 6}, {4, 5, 6}, {5, 2, 6}};
  long splits = 0;
  EXPECT_EQ(split_t_junctions(m, 1e-9, &splits).triangles.size(), m.triangles.size());
  EXPECT_EQ(splits, 0);
}

}  // namespace
}  // namespace cadnurbs
