// with_crease_normals: the welded STL cube (sharp at 30 degrees, one normal per corner at 100), a
// tessellated cylinder (smooth sides, sharp caps), and the edge kinds that never join; edges near the
// crease angle judged as its definition says, and the same bits from any number of threads.
#include "analysis/normals/crease_normals.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

#include "analysis/mesh/weld_vertices.hpp"
#include "core/worker_threads.hpp"
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

// Two triangles on the edge (0,0,0)-(length,0,0), the second at `dihedral` radians from the first; returns
// whether with_crease_normals joins them at `crease` and whether the definition does: atan2 of the unit
// normals' cross and dot products below the crease angle.
std::pair<bool, bool> joined_and_defined(double length, double width, double dihedral, double crease) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {length, 0, 0}, {0.3 * length, width, 0},
                 {0.6 * length, -width * std::cos(dihedral), width * std::sin(dihedral)}};
  m.triangles = {{0, 1, 2}, {1, 0, 3}};
  CreaseNormalsReport report;
  crease_normals(m, crease, &report);
  const Eigen::Vector3d n1 = face_normal(m, 0), n2 = face_normal(m, 1);
  auto unit = [&](int t) {
    const auto& T = m.triangles[t];
    const Eigen::Vector3d n = (m.positions[T[1]] - m.positions[T[0]]).cross(m.positions[T[2]] - m.positions[T[0]]);
    return Eigen::Vector3d(n / n.norm());
  };
  const Eigen::Vector3d u1 = unit(0), u2 = unit(1);
  EXPECT_LE((u1 - n1).norm() + (u2 - n2).norm(), 1e-15);
  return {report.smooth_edges == 1, std::atan2(u1.cross(u2).norm(), u1.dot(u2)) < crease};
}

// Most edges are judged without the atan2 (crease_normals.cpp: SmoothTest); at and around the crease
// angle, down to a few ulps, and at every scale, the judgement must be the atan2's.
TEST(CreaseNormals, EdgesNearTheCreaseAngleAreJudgedAsTheDefinitionSays) {
  int joined = 0, apart = 0;
  for (const double crease : {0.0, 1e-4, 0.01, 30 * degrees, 45 * degrees, 89.99 * degrees, 90 * degrees, 135 * degrees})
    for (const double length : {1e-40, 1e-3, 1.0, 7e5, 1e60})
      for (const double offset : {-1e-3, -1e-7, -1e-10, -1e-13, -1e-15, 0.0, 1e-15, 1e-13, 1e-10, 1e-7, 1e-3})
        for (const double width : {0.01, 1.0, 3.0}) {
          const auto [by_crease_normals, by_definition] = joined_and_defined(length, width * length, crease + offset, crease);
          EXPECT_EQ(by_crease_normals, by_definition)
              << "crease " << crease << " length " << length << " offset " << offset << " width " << width;
          ++(by_definition ? joined : apart);
        }
  EXPECT_GT(joined, 300);  // both sides of the angle are tried
  EXPECT_GT(apart, 300);
}

// The edges' angles and the groups' sums are shared out to worker threads: any count gives the same bits.
TEST(CreaseNormals, AnyThreadCountGivesTheSameBits) {
  const TriangleMesh soup = test::stl_cylinder(3.0, 2.0, 500);
  TriangleMesh welded = weld_vertices(soup, default_weld_tolerance(soup));
  for (std::size_t v = 0; v < welded.positions.size(); ++v)  // a rough surface: angles on both sides of 30
    welded.positions[v] += 0.02 * Eigen::Vector3d(std::sin(7.0 * v), std::cos(5.0 * v), std::sin(3.0 * v));
  set_worker_threads(1);
  CreaseNormalsReport one_report;
  const CornerNormals one = crease_normals(welded, 30 * degrees, &one_report);
  EXPECT_GT(one_report.smooth_edges, 100);
  EXPECT_GT(one_report.sharp_edges, 100);
  for (const int threads : {2, 3, 7}) {
    set_worker_threads(threads);
    CreaseNormalsReport report;
    const CornerNormals shared = crease_normals(welded, 30 * degrees, &report);
    EXPECT_EQ(shared.normals, one.normals) << threads << " threads";
    EXPECT_EQ(shared.corner_normal, one.corner_normal) << threads << " threads";
    EXPECT_EQ(report.smooth_edges, one_report.smooth_edges) << threads << " threads";
    EXPECT_EQ(report.sharp_edges, one_report.sharp_edges) << threads << " threads";
  }
  set_worker_threads(0);
}

}  // namespace
}  // namespace cadnurbs
