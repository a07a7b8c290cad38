// Assembly tree, names, colours and units through XCAF, on small corpus files with known content.
#include <gtest/gtest.h>

#include <functional>

#include "core/bounding_box.hpp"
#include "corpus_manifest.hpp"
#include "core/length_unit.hpp"
#include "formats/iges/iges_reader.hpp"
#include "formats/step/step_reader.hpp"

namespace cadnurbs::test {
namespace {

void visit_nodes(const SceneNode& node, const std::function<void(const SceneNode&)>& visit) {
  visit(node);
  for (const auto& child : node.children) visit_nodes(child, visit);
}

TEST(XcafStructure, AssemblyNamesTransformsAndColours) {
  // The CAx-IF as1 assembly: plate, two l-bracket assemblies (bracket + 3 nut-bolt assemblies), rod
  // assembly; 18 part instances, 160 faces, every part coloured.
  const BrepTranslation t = read_step(corpus_file("step/as1-oc-214.stp"));
  EXPECT_EQ(t.scene.root.name, "as1");
  EXPECT_EQ(t.scene.unit.name, "mm");
  EXPECT_EQ(t.scene.source_unit.name, "mm");
  std::map<std::string, int> names;
  int moved = 0, coloured_parts = 0, parts = 0;
  visit_nodes(t.scene.root, [&](const SceneNode& node) {
    ++names[node.name];
    if (!node.transform.matrix().isIdentity(1e-12)) ++moved;
    if (!node.shapes.empty()) {
      ++parts;
      if (node.colour) ++coloured_parts;
    }
  });
  EXPECT_EQ(names["l-bracket-assembly_1"] + names["l-bracket-assembly_2"], 2);
  EXPECT_EQ(names["plate_1"], 1);
  EXPECT_EQ(names["rod_1"], 1);
  EXPECT_EQ(names["nut-bolt-assembly_1"], 2);
  EXPECT_EQ(parts, 18);
  EXPECT_EQ(coloured_parts, parts);
  EXPECT_GT(moved, 10);
  // Face names follow the solid's face map.
  int faces = 0;
  for_each_shape(t.scene, [&](const Shape& shape, const Eigen::Affine3d&, const Colour&) {
    ++faces;
    EXPECT_EQ(shape.source_entity.rfind("face ", 0), 0u) << shape.source_entity;
  });
  EXPECT_EQ(faces, 160);
}

TEST(XcafStructure, LengthsAreMillimetresWhateverTheFileUnit) {
  // goteborg: the same hull in metres as STEP and IGES; its bounding box is about 6.1 m long.
  for (const char* relative : {"step/goteborg.step", "iges/goteborg.iges"}) {
    const std::string path = corpus_file(relative);
    const BrepTranslation t = std::string(relative).rfind("step/", 0) == 0 ? read_step(path) : read_iges(path);
    EXPECT_EQ(t.scene.unit.name, "mm") << relative;
    EXPECT_EQ(t.scene.source_unit.name, "m") << relative;
    EXPECT_EQ(t.scene.source_unit.millimetres, 1000.0) << relative;
    const auto box = scene_bounding_box(t.scene);
    EXPECT_NEAR(box.sizes().x(), 6119, 10) << relative;
  }
  EXPECT_EQ(read_step(corpus_file("step/dm1-id-214.stp")).scene.source_unit.name, "inch");
  EXPECT_EQ(read_iges(corpus_file("iges/side.iges")).scene.source_unit.name, "inch");
}

TEST(XcafStructure, UnitNamesFromStepAndIges) {
  EXPECT_EQ(length_unit_named("millimetre")->name, "mm");
  EXPECT_EQ(length_unit_named("MM")->millimetres, 1.0);
  EXPECT_EQ(length_unit_named("INCH")->millimetres, 25.4);
  EXPECT_EQ(length_unit_named("IN")->name, "inch");
  EXPECT_EQ(length_unit_named("metre")->millimetres, 1000.0);
  EXPECT_EQ(length_unit_named("FOOT")->name, "ft");
  EXPECT_EQ(length_unit_named("MIL")->millimetres, 0.0254);
  EXPECT_FALSE(length_unit_named("furlong"));
}

}  // namespace
}  // namespace cadnurbs::test
