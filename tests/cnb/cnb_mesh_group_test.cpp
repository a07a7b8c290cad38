// Mesh groups (.cnb shape kind 6): the meshes of one node, such as the colours of one body, coded as one
// traversal. Each decodes as the same triangles with its own name and colour; meshes meeting along an edge
// share its vertices in the file, so the group is smaller than the same meshes coded apart; vertices of one
// mesh at one position stay apart; a mesh met before stays a repeat.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <map>
#include <numbers>

#include "formats/cnb/cnb_reader.hpp"
#include "formats/cnb/cnb_writer.hpp"
#include "tests/cnb/expect_same_mesh_on_grid.hpp"

namespace cadnurbs {
namespace {

// A torus of n x m quads whose triangles are dealt to `parts` meshes by bands of u, each mesh with its own
// vertices (those on a band's edge are in both meshes, at the same position).
std::vector<TriangleMesh> torus_bands(int n, int m, int parts) {
  std::vector<TriangleMesh> meshes(parts);
  std::vector<std::map<int, int>> own(parts);
  auto position = [&](int i, int j) {
    const double u = 2 * std::numbers::pi * ((i + n) % n) / n, v = 2 * std::numbers::pi * ((j + m) % m) / m;
    return Eigen::Vector3d((10 + 3 * std::cos(v)) * std::cos(u), (10 + 3 * std::cos(v)) * std::sin(u), 3 * std::sin(v));
  };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const int part = i * parts / n;
      auto vertex = [&](int a, int b) {
        const int key = ((a + n) % n) * m + (b + m) % m;
        const auto [at, is_new] = own[part].emplace(key, static_cast<int>(meshes[part].positions.size()));
        if (is_new) meshes[part].positions.push_back(position(a, b));
        return at->second;
      };
      meshes[part].triangles.push_back({vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1)});
      meshes[part].triangles.push_back({vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1)});
    }
  return meshes;
}

// Two flat 3 x 3 sheets of unit squares at the same place, with vertices of their own, in one mesh.
TriangleMesh doubled_sheet() {
  TriangleMesh mesh;
  for (int copy = 0; copy < 2; ++copy) {
    const int first = static_cast<int>(mesh.positions.size());
    for (int i = 0; i <= 3; ++i)
      for (int j = 0; j <= 3; ++j) mesh.positions.emplace_back(i, j, -20);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const int a = first + i * 4 + j, b = a + 4;
        mesh.triangles.push_back({a, b, b + 1});
        mesh.triangles.push_back({a, b + 1, a + 1});
      }
  }
  return mesh;
}

struct Written {
  std::string bytes;
  double step = 0;
  int groups = 0;
  Scene decoded;
};

Written round_trip(const Scene& scene) {
  CnbOptions options;
  options.max_deviation = 0.01;
  options.free_mesh_points = false;  // every vertex where rounding puts it: compared by position
  CnbWriteReport report;
  Written w;
  w.bytes = write_cnb(scene, options, &report);
  w.step = report.point_step;
  w.groups = report.mesh_groups;
  w.decoded = read_cnb(w.bytes, "group.cnb");
  return w;
}

TEST(CnbMeshGroup, ColoursOfOneBodyShareTheirEdgesAndDecodeApart) {
  std::vector<TriangleMesh> meshes = torus_bands(36, 12, 3);
  meshes.push_back(doubled_sheet());
  const std::vector<Colour> colours{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.5, 0.5, 0.5}};
  Scene together, apart;
  together.root.name = apart.root.name = "part";
  for (size_t k = 0; k < meshes.size(); ++k) {
    const Shape shape{"band " + std::to_string(k), meshes[k], colours[k]};
    together.root.shapes.push_back(shape);
    SceneNode node;
    node.shapes.push_back(shape);
    apart.root.children.push_back(node);  // one mesh per node: no group
  }
  const Written grouped = round_trip(together), alone = round_trip(apart);
  EXPECT_EQ(grouped.groups, 1);
  EXPECT_EQ(alone.groups, 1);  // the doubled sheet alone: a group of one, for its second sheet, a copy
  ASSERT_EQ(grouped.decoded.root.shapes.size(), meshes.size());
  for (size_t k = 0; k < meshes.size(); ++k) {
    SCOPED_TRACE("mesh " + std::to_string(k));
    const Shape& shape = grouped.decoded.root.shapes[k];
    EXPECT_EQ(shape.name, "band " + std::to_string(k));
    ASSERT_TRUE(shape.colour);
    EXPECT_NEAR(shape.colour->r, colours[k].r, 1.0 / 65535);
    EXPECT_NEAR(shape.colour->b, colours[k].b, 1.0 / 65535);
    expect_same_mesh_on_grid(meshes[k], std::get<TriangleMesh>(shape.geometry), grouped.step);
  }
  std::cout << "4 meshes in one node: " << grouped.bytes.size() << " bytes; one per node: " << alone.bytes.size()
            << " bytes\n";
  EXPECT_LT(grouped.bytes.size(), alone.bytes.size());
}

TEST(CnbMeshGroup, AMeshMetBeforeStaysARepeat) {
  const std::vector<TriangleMesh> bands = torus_bands(24, 8, 2);
  Scene scene, without_repeat;
  scene.root.shapes = {{"a", bands[0], std::nullopt}, {"b", bands[1], std::nullopt}, {"a again", bands[0], std::nullopt}};
  without_repeat.root.shapes = {scene.root.shapes[0], scene.root.shapes[1]};
  const Written w = round_trip(scene), two = round_trip(without_repeat);
  EXPECT_EQ(w.groups, 1);
  ASSERT_EQ(w.decoded.root.shapes.size(), 3u);
  const auto& first = std::get<TriangleMesh>(w.decoded.root.shapes[0].geometry);
  const auto& again = std::get<TriangleMesh>(w.decoded.root.shapes[2].geometry);
  EXPECT_EQ(again.positions, first.positions);
  EXPECT_EQ(again.triangles, first.triangles);
  expect_same_mesh_on_grid(bands[1], std::get<TriangleMesh>(w.decoded.root.shapes[1].geometry), w.step);
  // A repeat costs a kind byte, a name and a back reference: far less than a band.
  EXPECT_LT(w.bytes.size(), two.bytes.size() + 16);
}

}  // namespace
}  // namespace cadnurbs
