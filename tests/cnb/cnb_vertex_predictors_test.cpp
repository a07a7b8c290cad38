// The vertex predictors of a traversal-coded mesh (.cnb format version 8, cnb_vertex_predictors.hpp): each
// exact, up to rounding, on the shape it is made for (closed forms), and a mesh whose caps are fans of a
// circle's polygon coding smaller with them than with the parallelogram alone, to the same triangles.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "formats/cnb/cnb_reader.hpp"
#include "formats/cnb/cnb_vertex_predictors.hpp"
#include "formats/cnb/cnb_writer.hpp"
#include "formats/common/file_io.hpp"
#include "tests/cnb/capped_cylinder.hpp"
#include "tests/cnb/cnb_file_header.hpp"

namespace cadnurbs {
namespace {

using cnb::GridPoint;

// The point of a circle of `radius` grid steps about (100, -50, 7) in a tilted plane, at `angle`, rounded.
GridPoint on_circle(double radius, double angle) {
  const double x = radius * std::cos(angle), y = radius * std::sin(angle);
  return {std::llround(100 + x), std::llround(-50 + 0.6 * y), std::llround(7 + 0.8 * y)};
}

double distance(const GridPoint& a, const GridPoint& b) {
  double s = 0;
  for (int k = 0; k < 3; ++k) s += static_cast<double>(a[k] - b[k]) * static_cast<double>(a[k] - b[k]);
  return std::sqrt(s);
}

// On a 24-gon of radius 1000 steps each step is a chord of 261 steps. Continued straight, the next point
// misses by 2 r sin(pi/24) sin(2 pi/24) = 68 steps; the arc misses only by the rounding of its three
// points (each within sqrt(3)/2 of the circle's), a few steps at most.
TEST(CnbVertexPredictors, TheArcContinuesACirclesPolygon) {
  const double r = 1000, step = 2 * std::numbers::pi / 24;
  double worst_arc = 0, best_straight = 1e9;
  for (int i = 0; i < 24; ++i) {
    const GridPoint c2 = on_circle(r, i * step), c1 = on_circle(r, (i + 1) * step), c0 = on_circle(r, (i + 2) * step);
    const GridPoint next = on_circle(r, (i + 3) * step);
    worst_arc = std::max(worst_arc, distance(cnb::arc_continuation(c0, c1, c2), next));
    const GridPoint straight{2 * c0[0] - c1[0], 2 * c0[1] - c1[1], 2 * c0[2] - c1[2]};
    best_straight = std::min(best_straight, distance(straight, next));
  }
  EXPECT_LT(worst_arc, 6.0);
  EXPECT_GT(best_straight, 60.0);
}

// Along a line the arc is the step repeated, exactly; with a step of length 0 it goes straight on.
TEST(CnbVertexPredictors, TheArcGoesStraightOnAlongALine) {
  EXPECT_EQ(cnb::arc_continuation({30, 20, 10}, {20, 15, 10}, {10, 10, 10}), (GridPoint{40, 25, 10}));
  EXPECT_EQ(cnb::arc_continuation({30, 20, 10}, {20, 15, 10}, {20, 15, 10}), (GridPoint{40, 25, 10}));
  EXPECT_EQ(cnb::arc_continuation({30, 20, 10}, {30, 20, 10}, {0, 0, 0}), (GridPoint{30, 20, 10}));
}

// On a fan about a centre, the spoke's mirror image of the last rim point is the next rim point.
TEST(CnbVertexPredictors, TheMirrorContinuesAFan) {
  const double r = 800, step = 2 * std::numbers::pi / 20;
  const GridPoint centre = on_circle(0, 0);
  double worst = 0;
  for (int i = 0; i < 20; ++i) {
    const GridPoint before = on_circle(r, i * step), spoke = on_circle(r, (i + 1) * step);
    worst = std::max(worst, distance(cnb::mirrored_apex(centre, spoke, before), on_circle(r, (i + 2) * step)));
  }
  EXPECT_LT(worst, 4.0);
  EXPECT_EQ(cnb::mirrored_apex({0, 0, 0}, {10, 0, 0}, {3, 4, 0}), (GridPoint{3, -4, 0}));
  EXPECT_EQ(cnb::mirrored_apex({5, 5, 5}, {5, 5, 5}, {3, 4, 0}), (GridPoint{7, 6, 10}));  // the parallelogram
}

struct Written {
  std::string bytes;
  TriangleMesh decoded;
};

Written written(const TriangleMesh& mesh, bool predictors, bool gate_shapes = true) {
  Scene scene;
  scene.root.name = "pin";
  scene.root.shapes.push_back({"pin", mesh, std::nullopt});
  CnbOptions options;
  options.max_deviation = 0.001;
  options.free_mesh_points = false;  // each vertex at its nearest grid point, so both decode alike
  options.vertex_predictors = predictors;
  options.gate_shapes = gate_shapes;
  Written w;
  w.bytes = write_cnb(scene, options);
  w.decoded = std::get<TriangleMesh>(read_cnb(w.bytes, "pin.cnb").root.shapes.at(0).geometry);
  return w;
}

// The caps' rims are where the parallelogram misses by a chord and the arcs do not: with the predictors
// the file is at least a fifth smaller (measured: 129 against 205 bytes), and decodes to the same
// triangles on the same grid points.
TEST(CnbVertexPredictors, APinsCapsCodeSmallerWithThePredictors) {
  const TriangleMesh pin = capped_cylinder(48, 0.3, 1.0);
  const Written with = written(pin, true), without = written(pin, false);
  EXPECT_LT(static_cast<double>(with.bytes.size()), 0.8 * static_cast<double>(without.bytes.size()))
      << with.bytes.size() << " against " << without.bytes.size();
  EXPECT_EQ(with.decoded.positions, without.decoded.positions);
  EXPECT_EQ(with.decoded.triangles, without.decoded.triangles);
  EXPECT_EQ(with.decoded.triangles.size(), pin.triangles.size());
}

// Without predictors a version 8 mesh is a version 7 one: the period's x is 2 x + 0 = 0 either way, so the
// same bytes read as version 7 give the same mesh. With them, read as version 7, they do not. (Version 9
// codes symbols and earlier vertices otherwise: these files are written as version 8.)
TEST(CnbVertexPredictors, AMeshWithoutPredictorsIsAVersionSevenMesh) {
  const TriangleMesh pin = capped_cylinder(48, 0.3, 1.0);
  const Written without = written(pin, false, false), with = written(pin, true, false);
  ASSERT_EQ(without.bytes[4], 8);
  const auto mesh_of = [](const std::string& file) {
    return std::get<TriangleMesh>(read_cnb(file, "pin.cnb").root.shapes.at(0).geometry);
  };
  const TriangleMesh old = mesh_of(with_version(without.bytes, 7));
  EXPECT_EQ(old.positions, without.decoded.positions);
  EXPECT_EQ(old.triangles, without.decoded.triangles);
  bool same = false;
  try {
    const TriangleMesh misread = mesh_of(with_version(with.bytes, 7));
    same = misread.positions == with.decoded.positions && misread.triangles == with.decoded.triangles;
  } catch (const FileError&) {
  }
  EXPECT_FALSE(same);
}

}  // namespace
}  // namespace cadnurbs
