// The thesis's float accounting (seed 001, §6.1) and the storage crossover, on shapes whose counts are
// known in closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "report/storage_crossover.hpp"
#include "report/storage_accounting.hpp"
#include "analysis_shapes.hpp"

using namespace cadnurbs;

namespace {
Scene scene_of(std::vector<Shape> shapes) {
  Scene scene;
  scene.root.shapes = std::move(shapes);
  return scene;
}
}  // namespace

TEST(StorageAccounting, ASphereCountsFourFloatsPerControlPointAndOnePerKnot) {
  const TrimmedSurface sphere = test::sphere(10.0);
  ASSERT_EQ(sphere.surface.u_count, 9);  // four rational arcs round
  ASSERT_EQ(sphere.surface.v_count, 5);  // two arcs pole to pole
  const NurbsStorage s = nurbs_storage(scene_of({Shape{"sphere", sphere, std::nullopt}}));
  EXPECT_EQ(s.surfaces, 1);
  EXPECT_EQ(s.control_points, 45);
  EXPECT_EQ(s.knots, 12 + 8);
  EXPECT_EQ(s.floats, 4 * 45 + 20);
  EXPECT_EQ(s.trim_floats, 0);
  EXPECT_EQ(s.total_floats(), 200);
}

TEST(StorageAccounting, TrimmingCurvesAndPolygonsAreCountedApart) {
  // An annulus: two loops, each a circle of four rational quadratic arcs (9 points, 12 knots).
  const TrimmedSurface annulus = test::trimmed_square(10.0, 0.4, 0.2);
  PolygonMesh square;
  square.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  square.polygons = {{0, 1, 2, 3}};
  const NurbsStorage s = nurbs_storage(scene_of({Shape{"annulus", annulus, std::nullopt}, Shape{"square", square, std::nullopt}}));
  EXPECT_EQ(s.floats, 4 * 4 + 8);  // bilinear square: 2x2 points, 4 + 4 knots
  EXPECT_EQ(s.trim_curves, 2);
  EXPECT_EQ(s.trim_control_points, 18);
  EXPECT_EQ(s.trim_floats, 3 * 18 + 24);
  EXPECT_EQ(s.polygon_floats, 12);
  EXPECT_EQ(s.polygon_corners, 4);
  EXPECT_EQ(s.total_floats(), 24 + 78 + 12);
}

TEST(StorageAccounting, AMeshCountsIndexedAndSoupForms) {
  TriangleMesh cube;
  for (int i = 0; i < 8; ++i) cube.positions.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  for (int t = 0; t < 12; ++t) cube.triangles.push_back({t % 8, (t + 1) % 8, (t + 2) % 8});
  const MeshStorage s = mesh_storage(cube);
  EXPECT_EQ(s.indexed_floats, 24);
  EXPECT_EQ(s.indexed_integers, 36);
  EXPECT_EQ(s.indexed_floats_with_normals, 48);
  EXPECT_EQ(s.soup_floats, 108);
  EXPECT_EQ(s.soup_floats_with_normals, 144);
}

TEST(StorageCrossover, InterpolatesOnTheLogLogLineBetweenTheBracketingPoints) {
  // bytes = 100 / D: equal to 3162.3 at D = 100 / 3162.3.
  const Crossover c = storage_crossover({{0.01, 10000}, {1, 100}, {0.1, 1000}}, 3162.3);
  ASSERT_TRUE(c.deviation.has_value());
  EXPECT_NEAR(*c.deviation, 100 / 3162.3, 1e-12);
  EXPECT_FALSE(c.mesh_larger_everywhere);
}

TEST(StorageCrossover, SaysWhichSideWinsWhenTheCurvesDoNotCross) {
  const Crossover larger = storage_crossover({{1, 500}, {0.1, 5000}}, 400);
  EXPECT_FALSE(larger.deviation.has_value());
  EXPECT_TRUE(larger.mesh_larger_everywhere);
  const Crossover smaller = storage_crossover({{1, 50}, {0.1, 300}}, 400);
  EXPECT_FALSE(smaller.deviation.has_value());
  EXPECT_FALSE(smaller.mesh_larger_everywhere);
}
