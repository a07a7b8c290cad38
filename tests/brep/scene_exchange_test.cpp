// A small assembly written as STEP and IGES and read back: tree, names, placements, colours, and a mesh
// written as planar faces.
#include <gtest/gtest.h>

#include <BRepPrimAPI_MakeBox.hxx>

#include "core/bounding_box.hpp"
#include "formats/brep/xcaf_to_scene.hpp"
#include "formats/iges/iges_reader.hpp"
#include "formats/iges/iges_writer.hpp"
#include "formats/step/step_reader.hpp"
#include "formats/step/step_writer.hpp"
#include "occt_reference.hpp"
#include "temporary_folder.hpp"
#include "trimmed_measure.hpp"

namespace cadnurbs::test {
namespace {

const Colour red{0.8, 0.1, 0.1}, blue{0.1, 0.2, 0.9}, green{0.1, 0.7, 0.2};

// bench: "box A" (red, one face blue), "box B" (placed: turned 90 degrees about z, moved 50 in x),
// "tetra" (green, a closed triangle mesh).
Scene bench() {
  Scene box = shape_to_scene(BRepPrimAPI_MakeBox(10, 20, 30).Shape(), "box").scene;
  Scene scene;
  scene.root.name = "bench";
  SceneNode a = box.root;
  a.name = "box A";
  a.colour = red;
  a.shapes[2].colour = blue;
  SceneNode b = box.root;
  b.name = "box B";
  b.transform = Eigen::Translation3d(50, 0, 0) * Eigen::AngleAxisd(0.5 * 3.14159265358979323846, Eigen::Vector3d::UnitZ());
  SceneNode tetra;
  tetra.name = "tetra";
  tetra.colour = green;
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 40}, {10, 0, 40}, {0, 10, 40}, {0, 0, 50}};
  mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  tetra.shapes.push_back({"tetrahedron", mesh, std::nullopt});
  scene.root.children = {a, b, tetra};
  return scene;
}

double scene_area(const Scene& scene) {
  double area = 0;
  for_each_shape(scene, [&](const Shape& shape, const Eigen::Affine3d& world, const Colour&) {
    if (const auto* t = std::get_if<TrimmedSurface>(&shape.geometry)) area += measure_trimmed_surface(*t, world).area;
    if (const auto* m = std::get_if<TriangleMesh>(&shape.geometry)) area += measure_mesh(*m, world).area;
  });
  return area;
}

const SceneNode* find(const SceneNode& node, const std::string& name) {
  if (node.name == name) return &node;
  for (const auto& child : node.children)
    if (const SceneNode* found = find(child, name)) return found;
  return nullptr;
}

// World-space box of a node's shapes, the node found by name.
Eigen::AlignedBox3d world_box(const Scene& scene, const std::string& name) {
  Eigen::AlignedBox3d box;
  std::function<void(const SceneNode&, const Eigen::Affine3d&, bool)> visit = [&](const SceneNode& node,
                                                                                  const Eigen::Affine3d& parent, bool in) {
    const Eigen::Affine3d world = parent * node.transform;
    in = in || node.name == name;
    if (in)
      for (const auto& shape : node.shapes)
        if (const auto* t = std::get_if<TrimmedSurface>(&shape.geometry))
          for (const auto& p : t->surface.points) box.extend(world * p);
    for (const auto& child : node.children) visit(child, world, in);
  };
  visit(scene.root, Eigen::Affine3d::Identity(), false);
  return box;
}

bool same_colour(const Colour& a, const Colour& b) {
  return std::abs(a.r - b.r) < 2e-3 && std::abs(a.g - b.g) < 2e-3 && std::abs(a.b - b.b) < 2e-3;
}

TEST(SceneExchange, StepKeepsTreeNamesPlacementsAndColours) {
  const Scene scene = bench();
  TemporaryFolder folder;
  const std::string path = folder.file("bench.step");
  write_step(path, scene);
  const BrepTranslation back = read_step(path);
  EXPECT_EQ(back.face_count, 6 + 6 + 4);
  EXPECT_TRUE(back.fallbacks.empty());
  EXPECT_NEAR(scene_area(back.scene) / scene_area(scene), 1.0, 1e-6);
  EXPECT_EQ(back.scene.root.name, "bench");
  for (const char* name : {"box A", "box B", "tetra"}) ASSERT_NE(find(back.scene.root, name), nullptr) << name;
  // Placement: box B's world box is where it was.
  const auto before = world_box(scene, "box B"), after = world_box(back.scene, "box B");
  EXPECT_TRUE(before.min().isApprox(after.min(), 1e-9)) << after.min().transpose();
  EXPECT_TRUE(before.max().isApprox(after.max(), 1e-9)) << after.max().transpose();
  EXPECT_NEAR(after.min().x(), 30, 1e-9);  // turned: y extent 20 became x extent
  // Colours: box A red with one blue face, tetra green.
  int blue_faces = 0, red_faces = 0;
  for_each_shape(*find(back.scene.root, "box A"), Eigen::Affine3d::Identity(), Colour{},
                 [&](const Shape&, const Eigen::Affine3d&, const Colour& c) {
                   blue_faces += same_colour(c, blue) ? 1 : 0;
                   red_faces += same_colour(c, red) ? 1 : 0;
                 });
  EXPECT_EQ(blue_faces, 1);
  EXPECT_EQ(red_faces, 5);
  bool tetra_green = true;
  for_each_shape(*find(back.scene.root, "tetra"), Eigen::Affine3d::Identity(), Colour{},
                 [&](const Shape&, const Eigen::Affine3d&, const Colour& c) { tetra_green = tetra_green && same_colour(c, green); });
  EXPECT_TRUE(tetra_green);
  // Every part closed: three solids, box B once (its prototype is box A's geometry, but written apart).
  const OcctReference reference = occt_reference(path);
  EXPECT_EQ(reference.solids, 3);
  EXPECT_TRUE(reference.faces_all_in_solids);
}

TEST(SceneExchange, IgesKeepsFacesAreaAndColours) {
  const Scene scene = bench();
  TemporaryFolder folder;
  const std::string path = folder.file("bench.igs");
  write_iges(path, scene);
  const BrepTranslation back = read_iges(path);
  EXPECT_EQ(back.face_count, 16);
  EXPECT_TRUE(back.fallbacks.empty());
  EXPECT_NEAR(scene_area(back.scene) / scene_area(scene), 1.0, 1e-6);
  int blue_faces = 0, green_faces = 0;
  for_each_shape(back.scene, [&](const Shape&, const Eigen::Affine3d&, const Colour& c) {
    blue_faces += same_colour(c, blue) ? 1 : 0;
    green_faces += same_colour(c, green) ? 1 : 0;
  });
  EXPECT_EQ(blue_faces, 1);
  EXPECT_EQ(green_faces, 4);
}

}  // namespace
}  // namespace cadnurbs::test
