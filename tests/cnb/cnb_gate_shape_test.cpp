// Format version 9 (cnb_gate_shape.hpp, cnb_traversal_mesh_coding.cpp, cnb_vertex_values.hpp): the shape
// of the border after the gate against closed forms, and a plate with holes and a fan-capped pin coding
// smaller than as version 8, to the same triangles. (Border places a reader refuses: cnb_damage_test.cpp.)
#include <gtest/gtest.h>

#include <iostream>

#include <cmath>
#include <numbers>

#include "formats/cnb/cnb_gate_shape.hpp"
#include "formats/cnb/cnb_reader.hpp"
#include "formats/cnb/cnb_writer.hpp"
#include "formats/common/file_io.hpp"
#include "tests/cnb/capped_cylinder.hpp"

namespace cadnurbs {
namespace {

using cnb::GridPoint;

// The gate runs from (0,0,0) to (10,0,0) with its triangle's apex below it (y < 0), so the far side is
// y > 0. The border turns at `to` towards w by the angle between to -> from and to -> w.
int shape_towards(const GridPoint& w) { return cnb::gate_shape({0, 0, 0}, {10, 0, 0}, {5, -5, 0}, w); }

TEST(CnbGateShape, ClassesOfTheTurnAfterTheGate) {
  EXPECT_EQ(shape_towards({5, 5, 0}), 4);    // 45 degrees
  EXPECT_EQ(shape_towards({10, 10, 0}), 3);  // 90
  EXPECT_EQ(shape_towards({20, 5, 0}), 2);   // 153
  EXPECT_EQ(shape_towards({15, -5, 0}), 0);  // on the apex's side: closing would fold the surface
  // Out of the gate's plane: the candidate's normal (0, -100, 50) against the gate's (0, 0, -50), cos 0.45.
  EXPECT_EQ(shape_towards({10, 5, 10}), 1);
  // Just inside the 0.99 of |cos|: a tilt of 0.1 against 1 (cos 0.995) is still in the plane.
  EXPECT_EQ(shape_towards({10, 100, 10}), 3);
  EXPECT_EQ(cnb::gate_shape({0, 0, 0}, {10, 0, 0}, {5, -5, 0}, std::nullopt), 0);  // no edge after the gate
  EXPECT_EQ(cnb::gate_shape({3, 3, 3}, {3, 3, 3}, {5, -5, 0}, GridPoint{5, 5, 0}), 0);  // a gate of length 0
  EXPECT_EQ(shape_towards({10, 0, 0}), 0);  // an edge of length 0 after the gate
  // The same on the other side of the gate (the apex above it): the classes follow the apex.
  EXPECT_EQ(cnb::gate_shape({0, 0, 0}, {10, 0, 0}, {5, 5, 0}, GridPoint{5, -5, 0}), 4);
  EXPECT_EQ(cnb::gate_shape({0, 0, 0}, {10, 0, 0}, {5, 5, 0}, GridPoint{5, 5, 0}), 0);
}

struct Written {
  std::string bytes;
  TriangleMesh decoded;
};

Written written(const TriangleMesh& mesh, bool gate_shapes) {
  Scene scene;
  scene.root.shapes.push_back({"part", mesh, std::nullopt});
  CnbOptions options;
  options.max_deviation = 0.001;
  options.free_mesh_points = false;  // each vertex at its nearest grid point, so both decode alike
  options.gate_shapes = gate_shapes;
  Written w;
  w.bytes = write_cnb(scene, options);
  w.decoded = std::get<TriangleMesh>(read_cnb(w.bytes, "part.cnb").root.shapes.at(0).geometry);
  return w;
}

// A square plate of n x n cells (two triangles each) with `holes` cells left out along its diagonal: each
// hole is a boundary the traversal meets as earlier vertices, which version 9 names by their place along
// the border and version 8 by their number.
TriangleMesh plate_with_holes(int n, int holes) {
  TriangleMesh mesh;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) mesh.positions.emplace_back(0.25 * i, 0.25 * j, 0.0);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      if (i == j && i % (n / holes) == n / holes / 2) continue;
      const int a = i * (n + 1) + j, b = a + n + 1;
      mesh.triangles.push_back({a, b, b + 1});
      mesh.triangles.push_back({a, b + 1, a + 1});
    }
  return mesh;
}

void expect_smaller_and_the_same(const TriangleMesh& mesh, size_t most_bytes) {
  const Written version_9 = written(mesh, true), version_8 = written(mesh, false);
  EXPECT_EQ(version_9.bytes[4], 9);
  EXPECT_EQ(version_8.bytes[4], 8);
  EXPECT_EQ(version_9.decoded.positions, version_8.decoded.positions);
  EXPECT_EQ(version_9.decoded.triangles, version_8.decoded.triangles);
  EXPECT_EQ(version_9.decoded.triangles.size(), mesh.triangles.size());
  std::cout << version_9.bytes.size() << " bytes against version 8's " << version_8.bytes.size() << "\n";
  EXPECT_LE(version_9.bytes.size(), most_bytes);
  EXPECT_LT(version_9.bytes.size(), version_8.bytes.size());
}

// Measured: 306 bytes against 407 (385 before vertex values took contexts by a listed prediction).
TEST(CnbGateShape, APlateWithHolesCodesSmallerThanAsVersion8) {
  expect_smaller_and_the_same(plate_with_holes(40, 8), 306);
}

// Measured: 112 bytes against 129 (126 with the border's shape and places alone).
TEST(CnbGateShape, AFanCappedPinCodesSmallerThanAsVersion8) {
  expect_smaller_and_the_same(capped_cylinder(48, 0.3, 1.0), 112);
}

}  // namespace
}  // namespace cadnurbs
