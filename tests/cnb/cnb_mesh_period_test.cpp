// A traversal-coded mesh's period (.cnb format version 5): the move that carries a row of repeated cells
// onto itself is found, and the vertices of each cell after the first are predicted from the cell before.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

#include "formats/cnb/cnb_mesh_period.hpp"
#include "formats/cnb/cnb_reader.hpp"
#include "formats/cnb/cnb_writer.hpp"
#include "tests/cnb/expect_same_mesh_on_grid.hpp"

namespace cadnurbs {
namespace {

// A strip of `cells` cells `pitch` apart along y, in one piece: each cell a unit square of the strip
// (corners shared with its neighbours) raised to an apex inside it, four triangles; the apex at the
// same place in every cell, or jittered cell by cell.
TriangleMesh strip(int cells, double pitch, bool jittered) {
  TriangleMesh mesh;
  std::mt19937 random(3);
  for (int i = 0; i <= cells; ++i) {
    mesh.positions.emplace_back(0, i * pitch, 0);
    mesh.positions.emplace_back(1, i * pitch, 0);
  }
  for (int i = 0; i < cells; ++i) {
    const double dx = jittered ? 0.2 * (random() % 100) / 100.0 : 0, dy = jittered ? 0.2 * (random() % 100) / 100.0 : 0;
    const int apex = static_cast<int>(mesh.positions.size());
    mesh.positions.emplace_back(0.3 + dx, i * pitch + 0.35 + dy, 0.45);
    const int a = 2 * i, b = a + 1, c = a + 3, d = a + 2;  // the square's corners, counter-clockwise from above
    mesh.triangles.push_back({a, b, apex});
    mesh.triangles.push_back({b, c, apex});
    mesh.triangles.push_back({c, d, apex});
    mesh.triangles.push_back({d, a, apex});
  }
  return mesh;
}

struct Written {
  std::string bytes;
  CnbWriteReport report;
  TriangleMesh decoded;
};

Written round_trip(const TriangleMesh& mesh) {
  Scene scene;
  scene.root.shapes.push_back({"strip", mesh, std::nullopt});
  CnbOptions options;
  options.max_deviation = 0.01;
  options.free_mesh_points = false;  // every vertex where rounding puts it: compared by position below
  Written w;
  w.bytes = write_cnb(scene, options, &w.report);
  w.decoded = std::get<TriangleMesh>(read_cnb(w.bytes, "strip.cnb").root.shapes.at(0).geometry);
  return w;
}

TEST(CnbMeshPeriod, TheMoveThatRepeatsTheMostPoints) {
  std::vector<cnb::GridPoint> points;
  for (int i = 0; i < 12; ++i)
    for (const cnb::GridPoint& p : {cnb::GridPoint{0, 0, 0}, cnb::GridPoint{5, 3, 0}, cnb::GridPoint{9, 0, 4}})
      points.push_back({p[0], p[1] + 37 * i, p[2]});
  EXPECT_EQ(cnb::dominant_period(points), (cnb::GridPoint{0, 37, 0}));
  // Points where no move repeats eight of them.
  std::vector<cnb::GridPoint> scattered;
  std::mt19937 random(7);
  for (int i = 0; i < 40; ++i)
    scattered.push_back({static_cast<int64_t>(random() % 100000), static_cast<int64_t>(random() % 100000),
                         static_cast<int64_t>(random() % 100000)});
  EXPECT_EQ(cnb::dominant_period(scattered), (cnb::GridPoint{0, 0, 0}));
}

TEST(CnbMeshPeriod, ARowOfCellsIsPredictedCellByCell) {
  const double step = round_trip(strip(1, 1, false)).report.point_step;
  const double pitch = std::round(1.0 / step) * step;  // whole steps, so that rounding repeats the cells
  const TriangleMesh alike = strip(40, pitch, false), jittered = strip(40, pitch, true);
  const Written a = round_trip(alike), j = round_trip(jittered);
  expect_same_mesh_on_grid(alike, a.decoded, a.report.point_step);
  expect_same_mesh_on_grid(jittered, j.decoded, j.report.point_step);
  // The writer also writes the file without periods and keeps the smaller: the period is kept.
  EXPECT_EQ(a.report.periodic_meshes, 1);
  std::cout << "40 cells alike: " << a.bytes.size() << " bytes; apexes jittered: " << j.bytes.size() << " bytes\n";
  EXPECT_LT(2 * a.bytes.size(), j.bytes.size());
}

}  // namespace
}  // namespace cadnurbs
