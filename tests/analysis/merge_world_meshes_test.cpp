// merge_world_meshes: meshes in placed nodes become one world mesh per colour at the root; a curve stays
// in its node, and a node left empty goes.
#include "analysis/mesh/merge_world_meshes.hpp"

#include <gtest/gtest.h>

#include "core/nurbs_curve.hpp"

namespace cadnurbs {
namespace {

TriangleMesh unit_triangle() {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}};
  m.corner_normals.assign(3, Eigen::Vector3d(0, 0, 1));
  return m;
}

TEST(MergeWorldMeshes, OneMeshPerColourPlacedInTheWorld) {
  Scene scene;
  scene.root.name = "part";
  SceneNode red, moved, curve_node;
  red.colour = Colour{1, 0, 0};
  red.shapes.push_back({"a", unit_triangle(), std::nullopt});
  moved.transform.translation() = Eigen::Vector3d(10, 0, 0);
  moved.colour = Colour{1, 0, 0};
  moved.shapes.push_back({"b", unit_triangle(), std::nullopt});
  moved.shapes.push_back({"c", unit_triangle(), Colour{0, 0, 1}});
  curve_node.name = "wire";
  NurbsCurve line;
  line.order = 2;
  line.points = {{0, 0, 0}, {1, 1, 1}};
  line.knots = {0, 0, 1, 1};
  curve_node.shapes.push_back({"line", line, std::nullopt});
  scene.root.children = {red, moved, curve_node};

  const Scene merged = merge_world_meshes(scene);
  ASSERT_EQ(merged.root.shapes.size(), 2u);
  const auto& reds = std::get<TriangleMesh>(merged.root.shapes[0].geometry);
  EXPECT_EQ(merged.root.shapes[0].colour, (Colour{1, 0, 0}));
  EXPECT_EQ(reds.triangles.size(), 2u);
  EXPECT_EQ(reds.positions.size(), 6u);
  EXPECT_EQ(reds.positions[4], Eigen::Vector3d(11, 0, 0));
  EXPECT_TRUE(reds.corner_normals.empty());
  EXPECT_EQ(merged.root.shapes[1].colour, (Colour{0, 0, 1}));
  ASSERT_EQ(merged.root.children.size(), 1u);  // the two mesh nodes are gone, the curve's stays
  EXPECT_EQ(merged.root.children[0].name, "wire");
}

}  // namespace
}  // namespace cadnurbs
