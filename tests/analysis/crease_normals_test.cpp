// with_crease_normals: the welded STL cube (sharp at 30 degrees, one normal per corner at 100), a
// tessellated cylinder (smooth sides, sharp caps), and the edge kinds that never join.
#include "analysis/crease_normals.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

#include "analysis/weld_vertices.hpp"
#include "weld_test_meshes.hpp"

namespace cadnurbs {
namespace {

constexpr double degrees = std::numbers::pi / 180;

Eigen::Vector3d face_normal(const TriangleMesh& m, int t) {
  const auto& T = m.triangles[t];
  return (m.positions[T[1]] - m.positions[T[0]]).cross(m.positions[T[2]] - m.positions[T[0]]).normalized();
}

// Distinct (vertex, normal) pairs, normals compared within 1e-12.
int distinct_corner_normals(const TriangleMesh& m) {
  std::vector<std::pair<int, Eigen::Vector3d>> seen;
  for (size_t c = 0; c < m.corner_normals.size(); ++c) {
    const int v = m.triangles[c / 3][c % 3];
    bool found = false;
    for (const auto& [w, n] : seen) found = found || (w == v && (n - m.corner_normals[c]).norm() <= 1e-12);
    if (!found) seen.emplace_back(v, m.corner_normals[c]);
  }
  return static_cast<int>(seen.size());
}

TEST(CreaseNormals, CubeAt30DegreesHas24FaceNormals) {
  const TriangleMesh soup = test::stl_cube(2.0);
  const TriangleMesh welded = weld_vertices(soup, default_weld_tolerance(soup));
  ASSERT_EQ(welded.positions.size(), 8u);
  CreaseNormalsReport report;
  const TriangleMesh shaded = with_crease_normals(welded, 30 * degrees, &report);
  ASSERT_EQ(shaded.corner_normals.size(), 36u);
  EXPECT_EQ(distinct_corner_normals(shaded), 24);
  EXPECT_EQ(report.distinct_normals, 24);
  EXPECT_EQ(report.smooth_edges, 6);  // the face diagonals
  EXPECT_EQ(report.sharp_edges, 12);  // the cube's edges
  EXPECT_EQ(report.boundary_edges + report.non_manifold_edges + report.inconsistent_edges, 0);
  for (size_t c = 0; c < 36; ++c) {
    const Eigen::Vector3d n = face_normal(shaded, static_cast<int>(c / 3));
    EXPECT_LE((shaded.corner_normals[c] - n).norm(), 1e-12) << "corner " << c;
    EXPECT_GT(n.dot(shaded.positions[shaded.triangles[c / 3][0]]), 0);  // outward
  }
}

// Above 90 degrees every cube corner is one normal; weighting by corner angle makes it the diagonal
// although a face meets a corner with one triangle (90 degrees) or two (45 + 45). Weighting by
// triangle count or area would tilt it.
TEST(CreaseNormals, CubeAt100DegreesIsDiagonalByAngleWeights) {
  const TriangleMesh soup = test::stl_cube(2.0);
  CreaseNormalsReport report;
  const TriangleMesh shaded = with_crease_normals(weld_vertices(soup, default_weld_tolerance(soup)), 100 * degrees, &report);
  EXPECT_EQ(report.distinct_normals, 8);
  for (size_t c = 0; c < 36; ++c) {
    const Eigen::Vector3d diagonal = shaded.positions[shaded.triangles[c / 3][c % 3]].normalized();
    EXPECT_LE((shaded.corner_normals[c] - diagonal).norm(), 1e-12) << "corner " << c;
  }
}

TEST(CreaseNormals, CylinderSidesSmoothCapsSharp) {
  const int segments = 64;
  const TriangleMesh soup = test::stl_cylinder(3.0, 5.0, segments);
  WeldReport weld;
  const TriangleMesh welded = weld_vertices(soup, default_weld_tolerance(soup), &weld);
  ASSERT_EQ(welded.positions.size(), static_cast<size_t>(2 * segments + 2));
  CreaseNormalsReport report;
  const TriangleMesh shaded = with_crease_normals(welded, 30 * degrees, &report);
  EXPECT_EQ(report.sharp_edges, 2 * segments);  // the two rims
  // Rim vertices: one side normal, one cap normal; centres: one normal.
  EXPECT_EQ(report.distinct_normals, 2 * (2 * segments) + 2);
  double worst_side = 0, worst_cap = 0;
  for (size_t c = 0; c < shaded.corner_normals.size(); ++c) {
    const Eigen::Vector3d face = face_normal(shaded, static_cast<int>(c / 3));
    const Eigen::Vector3d& n = shaded.corner_normals[c];
    const Eigen::Vector3d& p = shaded.positions[shaded.triangles[c / 3][c % 3]];
    if (std::abs(face.z()) < 0.5) {
      const Eigen::Vector3d radial = Eigen::Vector3d(p.x(), p.y(), 0).normalized();
      worst_side = std::max(worst_side, (n - radial).norm());
    } else {
      worst_cap = std::max(worst_cap, (n - Eigen::Vector3d(0, 0, face.z() > 0 ? 1 : -1)).norm());
    }
  }
  std::printf("cylinder %d segments: side normals %.3g from radial, cap normals %.3g from axial\n", segments,
              worst_side, worst_cap);
  EXPECT_LE(worst_side, 1e-6);
  EXPECT_LE(worst_cap, 1e-12);

  // Shared: one normal per group, the same doubles as the spread ones, numbered by first corner.
  const CornerNormals shared = crease_normals(welded, 30 * degrees);
  ASSERT_EQ(shared.normals.size(), static_cast<size_t>(report.distinct_normals));
  ASSERT_EQ(shared.corner_normal.size(), shaded.corner_normals.size());
  int next = 0;
  for (size_t c = 0; c < shared.corner_normal.size(); ++c) {
    const int g = shared.corner_normal[c];
    ASSERT_LE(g, next) << "corner " << c;
    if (g == next) ++next;
    EXPECT_EQ(shared.normals[g], shaded.corner_normals[c]) << "corner " << c;
  }
}

// Two triangles folded flat onto each other across an edge, joined there by a crease angle above 180
// degrees: at each end of the edge the two corners' angle-weighted normals cancel, so each corner takes
// its own face's normal, the group's first corner in the group's slot and the other in a new one.
TEST(CreaseNormals, ACancelledGroupGivesEachCornerItsFaceNormal) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}, {1, 0, 3}};  // normals +z and -z; the second runs the shared edge 1 -> 0
  CreaseNormalsReport report;
  const CornerNormals shared = crease_normals(m, 4.0, &report);
  EXPECT_EQ(report.smooth_edges, 1);
  EXPECT_EQ(report.distinct_normals, 4);  // {A0, B1}, {A1, B0}, {A2}, {B2}
  ASSERT_EQ(shared.normals.size(), 6u);
  EXPECT_EQ(shared.corner_normal, (std::vector<int>{0, 1, 2, 4, 5, 3}));
  for (int c = 0; c < 6; ++c)
    EXPECT_EQ(shared.normals[shared.corner_normal[c]], Eigen::Vector3d(0, 0, c < 3 ? 1 : -1)) << "corner " << c;
}

// Two coplanar triangles join only across a shared edge with opposite directions; a third face on
// the same edge (non-manifold) or a flipped neighbour leaves them apart.
TEST(CreaseNormals, OnlyManifoldConsistentEdgesJoin) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0.1}};
  m.triangles = {{0, 1, 2}, {2, 1, 3}};
  CreaseNormalsReport report;
  with_crease_normals(m, 30 * degrees, &report);
  EXPECT_EQ(report.smooth_edges, 1);
  EXPECT_EQ(report.boundary_edges, 4);
  EXPECT_EQ(report.distinct_normals, 4);  // two shared corners joined: 6 corners, 4 normals

  m.triangles = {{0, 1, 2}, {1, 2, 3}};  // the second runs 1 -> 2 like the first
  with_crease_normals(m, 30 * degrees, &report);
  EXPECT_EQ(report.inconsistent_edges, 1);
  EXPECT_EQ(report.distinct_normals, 6);

  m.positions.push_back({1, 1, -0.1});
  m.triangles = {{0, 1, 2}, {2, 1, 3}, {2, 1, 4}};
  with_crease_normals(m, 30 * degrees, &report);
  EXPECT_EQ(report.non_manifold_edges, 1);
  EXPECT_EQ(report.distinct_normals, 9);
  EXPECT_THROW(with_crease_normals(m, -1, nullptr), std::invalid_argument);
}

}  // namespace
}  // namespace cadnurbs
