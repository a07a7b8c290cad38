// What the writer does to be small: repeated nodes written once (DEF/USE), no indent unless asked,
// planar polygons as one IndexedFaceSet; and that all of it reads back to the same world.
#include <gtest/gtest.h>

#include <regex>
#include <tuple>

#include "core/bounding_box.hpp"
#include "analysis/tessellation/plan_tessellation_hints.hpp"
#include "formats/vrml/vrml_reader.hpp"
#include "formats/vrml/vrml_writer.hpp"
#include "scene_comparison.hpp"
#include "test_scenes.hpp"

namespace cadnurbs {
namespace {

using vrml_test::with_encoding;

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// Five copies of one part (a cylinder and a trimmed plate) placed by translations, all red.
Scene five_copies() {
  Scene scene;
  scene.root.name = "row";
  for (int k = 0; k < 5; ++k) {
    SceneNode part;
    part.transform.translate(Eigen::Vector3d(30.0 * k, 0, 0));
    part.shapes.push_back({"", TrimmedSurface{vrml_test::quarter_cylinder(), {}}, Colour{1, 0, 0}});
    part.shapes.push_back({"", vrml_test::trimmed_plate(), Colour{1, 0, 0}});
    scene.root.children.push_back(part);
  }
  return scene;
}

// World-space points of every shape's geometry, in scene order: what a viewer draws.
std::vector<Eigen::Vector3d> world_points(const Scene& scene) {
  std::vector<Eigen::Vector3d> out;
  for_each_shape(scene, [&](const Shape& shape, const Eigen::Affine3d& world, const Colour&) {
    if (const auto* t = std::get_if<TrimmedSurface>(&shape.geometry))
      for (double u : {0.0, 0.3, 1.0})
        for (double v : {0.0, 0.6, 1.0}) out.push_back(world * surface_point(t->surface, u, v));
  });
  return out;
}

TEST(CompactWriting, RepeatedPartsAndAppearancesAreWrittenOnce) {
  const Scene scene = five_copies();
  for (VrmlEncoding encoding : {VrmlEncoding::vrml97, VrmlEncoding::x3d_classic, VrmlEncoding::x3d_xml}) {
    const std::string text = format_vrml(scene, with_encoding(encoding));
    const bool xml = encoding == VrmlEncoding::x3d_xml;
    // One shared Group of the part's two shapes, USE'd by the four other Transforms.
    EXPECT_EQ(count(text, xml ? "USE='_" : "USE _"), 4u + 1u) << text;  // + the second shape's Appearance
    EXPECT_EQ(count(text, xml ? "<Material" : "Material {"), 1u) << text;
    const Scene back = parse_vrml(text, "five");
    const auto a = world_points(scene), b = world_points(back);
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) EXPECT_LT((a[i] - b[i]).norm(), 1e-4) << i;
    // Shared nodes bring no names with them.
    for_each_shape(back, [&](const Shape& shape, const Eigen::Affine3d&, const Colour&) { EXPECT_EQ(shape.name, ""); });
  }
}

// Sharing compares nodes as written: two meshes whose points differ only below the written precision are
// one mesh in the file; a third with one more point (same type and fields, another array length) is not.
TEST(CompactWriting, MeshesEqualAsWrittenAreSharedAndOthersAreNot) {
  auto mesh = [](double nudge, bool extra_point) {
    TriangleMesh m;
    m.positions = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {10, 10, nudge}};
    m.triangles = {{0, 1, 2}, {2, 1, 3}};
    if (extra_point) m.positions.push_back({5, 5, 5});
    return m;
  };
  Scene scene;
  for (const auto& [x, nudge, extra] : {std::tuple{0.0, 0.0, false}, {20.0, 1e-9, false}, {40.0, 0.0, true}}) {
    SceneNode part;
    part.transform.translate(Eigen::Vector3d(x, 0, 0));
    part.shapes.push_back({"", mesh(nudge, extra), Colour{0, 0, 1}});
    scene.root.children.push_back(part);
  }
  const std::string text = format_vrml(scene, with_encoding(VrmlEncoding::x3d_classic));
  EXPECT_EQ(count(text, "IndexedFaceSet {"), 2u) << text;
  EXPECT_EQ(count(text, "Coordinate {"), 2u) << text;
}

TEST(CompactWriting, ANameThatLooksGeneratedSurvives) {
  Scene scene = vrml_test::single_shape_scene(TrimmedSurface{vrml_test::quarter_cylinder(), {}}, "_3");
  const std::string text = format_vrml(scene, with_encoding(VrmlEncoding::x3d_classic));
  EXPECT_EQ(parse_vrml(text, "named").root.shapes[0].name, "_3");
}

TEST(CompactWriting, NoIndentUnlessPretty) {
  const Scene scene = vrml_test::assembly_scene(false);
  for (VrmlEncoding encoding : {VrmlEncoding::vrml97, VrmlEncoding::x3d_classic, VrmlEncoding::x3d_xml}) {
    VrmlWriteOptions o = with_encoding(encoding);
    const std::string compact = format_vrml(scene, o);
    o.pretty = true;
    const std::string pretty = format_vrml(scene, o);
    // EXTERNPROTO interface lines are indented by the PROTO library; the scene itself is not.
    const std::string body = compact.substr(compact.find(encoding == VrmlEncoding::x3d_xml ? "<Scene>" : "WorldInfo"));
    EXPECT_FALSE(std::regex_search(body, std::regex("\n ")));
    EXPECT_TRUE(std::regex_search(pretty, std::regex("\n  ")));
    EXPECT_LT(compact.size(), pretty.size());
    vrml_test::expect_same_scene(scene, parse_vrml(compact, "compact"), o);
  }
}

TEST(CompactWriting, PolygonsAreOneFlatShadedFaceSetAndReadBackAsTheirFans) {
  PolygonMesh mesh{{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}, {3, 0, 0}, {3, 1, 0}}, {{0, 1, 2, 3}, {1, 4, 5, 2}}};
  const Scene scene = vrml_test::single_shape_scene(mesh);
  for (VrmlEncoding encoding : {VrmlEncoding::vrml97, VrmlEncoding::x3d_classic, VrmlEncoding::x3d_xml}) {
    const VrmlWriteOptions o = with_encoding(encoding);
    const std::string text = format_vrml(scene, o);
    EXPECT_NE(text.find(encoding == VrmlEncoding::x3d_xml ? "coordIndex='0 1 2 3 -1\n1 4 5 2'" : "coordIndex [0 1 2 3 -1\n1 4 5 2]"),
              std::string::npos)
        << text;
    EXPECT_EQ(text.find("creaseAngle"), std::string::npos);
    vrml_test::expect_same_scene(scene, parse_vrml(text, "polygons"), o);
  }
}

}  // namespace
}  // namespace cadnurbs

namespace cadnurbs {
namespace {

// uTessellation / vTessellation / tessellation as analysis/tessellation/plan_tessellation_hints computes them for the
// display deviation, in the surface's node of either dialect (VRML97: NurbsSurface), and none at 0.
TEST(CompactWriting, TessellationHintsAreWrittenForTheDisplayDeviation) {
  TrimmedSurface face = vrml_test::trimmed_plate();
  face.surface = vrml_test::quarter_cylinder();
  const Scene scene = vrml_test::single_shape_scene(face, "");
  const double d = 1e-4 * scene_bounding_box(scene).diagonal().norm();
  const TessellationHints expected = plan_tessellation_hints(face, d);
  ASSERT_GT(expected.u + expected.v, 0);  // the viewers' default is too coarse at this deviation
  for (auto encoding : {VrmlEncoding::vrml97, VrmlEncoding::x3d_classic, VrmlEncoding::x3d_xml}) {
    VrmlWriteOptions options = with_encoding(encoding);
    options.display_deviation = d;
    options.tessellation_hints = &plan_tessellation_hints;
    const std::string text = format_vrml(scene, options);
    const bool xml = encoding == VrmlEncoding::x3d_xml;
    auto field = [&](const std::string& name, int value) {
      return xml ? name + "='" + std::to_string(value) + "'" : name + " " + std::to_string(value);
    };
    if (expected.u > 0) EXPECT_EQ(count(text, field("uTessellation", expected.u)), 1u) << text;
    if (expected.v > 0) EXPECT_EQ(count(text, field("vTessellation", expected.v)), 1u) << text;
    for (size_t k = 0; k < expected.trim_segments[0].size(); ++k)
      if (expected.trim_segments[0][k] > 0)
        EXPECT_GE(count(text, field("tessellation", expected.trim_segments[0][k])), 1u) << text;
    EXPECT_EQ(parse_vrml(text, "hinted").root.shapes.size(), 1u);
    options.display_deviation = 0;
    const std::string plain = format_vrml(scene, options);
    EXPECT_FALSE(std::regex_search(plain, std::regex("essellation[ =']+[0-9]"))) << plain;
  }
}

}  // namespace
}  // namespace cadnurbs
