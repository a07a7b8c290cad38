// What the writer puts in a file: headers, EXTERNPROTO blocks, conventions, names, precision, refusals.
#include <gtest/gtest.h>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "core/geometry_error.hpp"
#include "formats/common/file_io.hpp"
#include "formats/vrml/classic_encoding.hpp"
#include "formats/vrml/nurbs_protos.hpp"
#include "formats/vrml/scene_to_nodes.hpp"
#include "formats/vrml/vrml_reader.hpp"
#include "formats/vrml/vrml_writer.hpp"
#include "test_scenes.hpp"

namespace cadnurbs {
namespace {

using vrml_test::with_encoding;

std::set<std::string> externproto_names(const std::string& text) {
  std::set<std::string> names;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (line.rfind("EXTERNPROTO ", 0) == 0) names.insert(line.substr(12, line.find(' ', 12) - 12));
  return names;
}

TEST(VrmlWriter, HeadersOfTheThreeEncodings) {
  const Scene scene = vrml_test::single_shape_scene(TrimmedSurface{vrml_test::quarter_cylinder(), {}});
  EXPECT_EQ(format_vrml(scene, with_encoding(VrmlEncoding::vrml97)).rfind("#VRML V2.0 utf8\nEXTERNPROTO ", 0), 0u);
  EXPECT_EQ(format_vrml(scene, with_encoding(VrmlEncoding::x3d_classic))
                .rfind("#X3D V3.3 utf8\nPROFILE Interchange\nCOMPONENT NURBS:4\n", 0),
            0u);
  const std::string xml = format_vrml(scene, with_encoding(VrmlEncoding::x3d_xml));
  EXPECT_NE(xml.find("<X3D profile='Interchange' version='3.3'>\n<head>\n<component name='NURBS' level='4'/>\n</head>"),
            std::string::npos);
  for (auto encoding : {VrmlEncoding::vrml97, VrmlEncoding::x3d_classic, VrmlEncoding::x3d_xml}) {
    const std::string text = format_vrml(scene, with_encoding(encoding));
    EXPECT_NE(text.find("generator cadnurbs"), std::string::npos);
    EXPECT_NE(text.find("unit mm"), std::string::npos);
    EXPECT_NE(text.find("controlPoint homogeneous"), std::string::npos);
    EXPECT_NE(text.find("NavigationInfo"), std::string::npos);
    EXPECT_NE(text.find("EXAMINE"), std::string::npos);
    EXPECT_NE(text.find("Viewpoint"), std::string::npos);
  }
}

TEST(VrmlWriter, ExternProtoBlockListsExactlyTheNurbsNodesUsed) {
  const std::set<std::string> vrml97_nurbs = {"NurbsSurface", "TrimmedSurface", "Contour2D", "NurbsCurve2D",
                                              "Polyline2D",   "NurbsCurve",     "NurbsGroup"};
  auto expect_exact = [&](const Scene& scene, const std::set<std::string>& expected) {
    const VrmlWriteOptions o = with_encoding(VrmlEncoding::vrml97);
    const std::string text = format_vrml(scene, o);
    EXPECT_EQ(externproto_names(text), expected) << text.substr(0, 3000);
    // Independently: the NURBS node types of the node graph.
    std::set<std::string> used;
    for (const auto& type : node_types_used(scene_to_nodes(scene, o)))
      if (vrml97_nurbs.count(type)) used.insert(type);
    EXPECT_EQ(used, expected);
    for (const auto& name : expected) {
      // The web3d URN only where view3dscene's own node of that name has our fields (proto_library.cpp).
      const std::string web3d = name == "NurbsSurface" || name == "NurbsGroup" ? "\"urn:web3d:vrml97:node:" + name + "\" " : "";
      EXPECT_NE(text.find("[" + web3d + "\"urn:inet:blaxxun.com:node:" + name + "\" \"cadnurbs-nurbs-protos.wrl#" +
                          name + "\"]"),
                std::string::npos)
          << name;
    }
  };
  expect_exact(vrml_test::single_shape_scene(TrimmedSurface{vrml_test::quarter_cylinder(), {}}), {"NurbsSurface"});
  expect_exact(vrml_test::single_shape_scene(vrml_test::trimmed_plate()),
               {"NurbsSurface", "TrimmedSurface", "Contour2D", "NurbsCurve2D", "Polyline2D"});
  expect_exact(vrml_test::single_shape_scene(vrml_test::octahedron_with_normals()), {});
  // Trimmed only by NURBS arcs: no Polyline2D declared.
  TrimmedSurface circle_only = vrml_test::trimmed_plate();
  circle_only.loops.pop_back();
  expect_exact(vrml_test::single_shape_scene(circle_only), {"NurbsSurface", "TrimmedSurface", "Contour2D", "NurbsCurve2D"});
}

TEST(VrmlWriter, ExternProtoUrlAndSelfContainedOption) {
  const Scene scene = vrml_test::single_shape_scene(vrml_test::trimmed_plate());
  VrmlWriteOptions o = with_encoding(VrmlEncoding::vrml97);
  o.protos_url = "https://example.org/protos.wrl";
  EXPECT_NE(format_vrml(scene, o).find("\"https://example.org/protos.wrl#NurbsSurface\""), std::string::npos);
  o.self_contained = true;
  const std::string text = format_vrml(scene, o);
  EXPECT_EQ(text.find("EXTERNPROTO"), std::string::npos);
  for (const auto& proto : nurbs_protos()) {
    // The PROTOs of nodes a scene of surfaces uses; NurbsPositionInterpolator is fit-path's alone.
    if (proto.name != "NurbsGroup" && proto.name != "NurbsCurve" && proto.name != "NurbsPositionInterpolator") {
      EXPECT_NE(text.find(proto.text), std::string::npos) << proto.name;
    }
  }
  // The reader skips the pasted PROTOs and still finds the geometry.
  const Scene back = parse_vrml(text, "self-contained");
  ASSERT_EQ(back.root.shapes.size(), 1u);
  EXPECT_EQ(std::get<TrimmedSurface>(back.root.shapes[0].geometry).loops.size(), 2u);
}

TEST(VrmlWriter, HomogeneousAndEuclideanControlPointsDiffer) {
  const Scene scene = vrml_test::single_shape_scene(TrimmedSurface{vrml_test::quarter_cylinder(), {}});
  for (auto encoding : {VrmlEncoding::vrml97, VrmlEncoding::x3d_classic, VrmlEncoding::x3d_xml}) {
    VrmlWriteOptions o = with_encoding(encoding);
    const std::string homogeneous = format_vrml(scene, o);
    o.homogeneous_control_points = false;
    const std::string euclidean = format_vrml(scene, o);
    // The corner point (10, 10, 0) of weight cos 45° is written as w·P = (7.0710678.., 7.0710678.., 0),
    // to 8.7e-6 (tau/2·w_min, tau = 1e-6 × the box diagonal √600).
    EXPECT_NE(homogeneous.find("\n7.07107 7.07107 0\n"), std::string::npos) << homogeneous;
    EXPECT_EQ(homogeneous.find("\n10 10 0\n"), std::string::npos);
    EXPECT_NE(euclidean.find("\n10 10 0\n"), std::string::npos) << euclidean;
    EXPECT_NE(euclidean.find("controlPoint euclidean"), std::string::npos);
    // Read with the wrong convention (no WorldInfo line to correct it), the corner moves.
    std::string unmarked = homogeneous;
    unmarked.replace(unmarked.find("controlPoint homogeneous"), 24, "cp");
    const Scene wrong = parse_vrml(unmarked, "unmarked", false);
    const auto& corner = std::get<TrimmedSurface>(wrong.root.shapes[0].geometry).surface.points[1];
    EXPECT_NEAR(corner.x(), 7.0710678, 1e-5);
    const Scene right = parse_vrml(unmarked, "unmarked", true);
    EXPECT_NEAR(std::get<TrimmedSurface>(right.root.shapes[0].geometry).surface.points[1].x(), 10.0, 1e-5);
  }
}

TEST(VrmlWriter, NamesBecomeUniqueLegalDefNamesAndComeBack) {
  const Scene scene = vrml_test::assembly_scene(false);
  const std::string text = format_vrml(scene, with_encoding(VrmlEncoding::x3d_classic));
  EXPECT_NE(text.find("DEF Assembly Transform") == std::string::npos ? text.find("DEF Assembly Group")
                                                                     : text.find("DEF Assembly Transform"),
            std::string::npos);
  EXPECT_NE(text.find("DEF Bracket_1 Transform"), std::string::npos);
  EXPECT_NE(text.find("DEF Bracket_1_2 Transform"), std::string::npos);
  EXPECT_NE(text.find("DEF _n_code_mesh Transform"), std::string::npos);
  EXPECT_NE(text.find("\"name Bracket_1 Bracket 1\""), std::string::npos);
  EXPECT_NE(text.find("\"name Bracket_1_2 Bracket 1\""), std::string::npos);
  EXPECT_NE(text.find("\"name _n_code_mesh Ünïcode mesh\""), std::string::npos);
  // Node colours: shared appearances, DEF'd once and USE'd after.
  EXPECT_NE(text.find("DEF Bracket_1_colour Appearance"), std::string::npos);
  EXPECT_NE(text.find("DEF Assembly_colour Appearance"), std::string::npos);
  EXPECT_NE(text.find("appearance USE Assembly_colour"), std::string::npos);
  // Every DEF is unique.
  std::set<std::string> defs;
  const std::regex def(R"(DEF ([^ ]+) )");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), def); it != std::sregex_iterator(); ++it)
    EXPECT_TRUE(defs.insert((*it)[1]).second) << (*it)[1];
  // And back.
  const Scene back = parse_vrml(text, "names");
  ASSERT_EQ(back.root.children.size(), 2u);
  EXPECT_EQ(back.root.children[0].name, "Bracket 1");
  EXPECT_EQ(back.root.children[1].name, "Bracket 1");
  EXPECT_EQ(back.root.children[1].children.at(0).name, "Ünïcode mesh");
  EXPECT_EQ(back.root.children[1].children.at(0).shapes.at(0).name, "");
}

TEST(VrmlWriter, ExplicitViewpointIsWrittenIdenticallyForDifferentScenes) {
  Viewpoint view;
  view.position = Eigen::Vector3d(12.345678901, -3, 400.5);
  view.orientation = Eigen::AngleAxisd(0.5, Eigen::Vector3d(0, 1, 1).normalized());
  auto viewpoint_line = [&](const Scene& scene) {
    VrmlWriteOptions o = with_encoding(VrmlEncoding::vrml97);
    o.viewpoint = view;
    const std::string text = format_vrml(scene, o);
    const size_t start = text.find("Viewpoint");
    return text.substr(start, text.find('\n', start) - start);
  };
  const std::string nurbs = viewpoint_line(vrml_test::single_shape_scene(TrimmedSurface{vrml_test::quarter_cylinder(), {}}));
  const std::string mesh = viewpoint_line(vrml_test::single_shape_scene(vrml_test::octahedron_with_normals()));
  EXPECT_EQ(nurbs, mesh);
  // Camera precision is 1e-6 of the position's length (400.7), whatever the scene.
  EXPECT_NE(nurbs.find("position 12.346 -3 400.5"), std::string::npos) << nurbs;
}

TEST(VrmlWriter, SignificantDigitsLimitEveryNumber) {
  const Scene scene = vrml_test::single_shape_scene(TrimmedSurface{vrml_test::quarter_cylinder(), {}});
  VrmlWriteOptions o = with_encoding(VrmlEncoding::x3d_classic);
  o.significant_digits = 3;
  const std::string text = format_vrml(scene, o);
  EXPECT_NE(text.find("\n7.07 7.07 0\n"), std::string::npos) << text;
  EXPECT_NE(text.find("weight [1 .707 1 1 .707 1]"), std::string::npos) << text;
  // Every number after the header has at most 3 significant digits.
  std::istringstream words(text.substr(text.find("NavigationInfo")));
  for (std::string word; words >> word;) {
    word.erase(0, word.find_first_not_of("[\"'"));
    if (word.empty() || !(std::isdigit(static_cast<unsigned char>(word[0])) || word[0] == '.' || word[0] == '-')) continue;
    std::string digits;
    for (char c : word.substr(0, word.find('e')))
      if (std::isdigit(static_cast<unsigned char>(c)) && !(digits.empty() && c == '0')) digits.push_back(c);
    while (!digits.empty() && digits.back() == '0') digits.pop_back();
    EXPECT_LE(digits.size(), 3u) << word;
  }
}

TEST(VrmlWriter, DefaultToleranceIsAMillionthOfTheDiagonal) {
  const Scene scene = vrml_test::single_shape_scene(TrimmedSurface{vrml_test::quarter_cylinder(), {}});
  // Control net box: 10 x 10 x 20.
  EXPECT_DOUBLE_EQ(effective_coordinate_tolerance(scene, {}), 1e-6 * std::sqrt(600.0));
  VrmlWriteOptions o;
  o.coordinate_tolerance = 0.25;
  EXPECT_EQ(effective_coordinate_tolerance(scene, o), 0.25);
}

TEST(VrmlWriter, RefusesDecreasingKnotsNamingTheEntity) {
  Scene scene = vrml_test::assembly_scene(false);
  std::get<TrimmedSurface>(scene.root.children[0].shapes[0].geometry).surface.u_knots = {0, 0, 0.5, 0.2, 1, 1};
  try {
    format_vrml(scene, {});
    FAIL() << "invalid scene accepted";
  } catch (const GeometryError& e) {
    EXPECT_EQ(e.entity(), "Assembly/Bracket 1/wall");
  }
  const auto path = (std::filesystem::temp_directory_path() / "cadnurbs_vrml_refused.x3dv").string();
  std::remove(path.c_str());
  try {
    write_vrml(path, scene, {});
    FAIL() << "invalid scene written";
  } catch (const FileError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(path + ": Assembly/Bracket 1/wall: ", 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos);
  }
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(VrmlWriter, RefusesSingularTransformsAndBadOptions) {
  Scene scene = vrml_test::assembly_scene(false);
  scene.root.children[1].transform = Eigen::Affine3d(Eigen::Scaling(1.0, 0.0, 1.0));
  try {
    format_vrml(scene, {});
    FAIL() << "singular transform accepted";
  } catch (const GeometryError& e) {
    EXPECT_EQ(e.entity(), "Assembly/Bracket 1");
  }
  VrmlWriteOptions o;
  o.significant_digits = 18;
  EXPECT_THROW(format_vrml(vrml_test::assembly_scene(false), o), std::invalid_argument);
  o.significant_digits = 0;
  o.coordinate_tolerance = -1;
  EXPECT_THROW(format_vrml(vrml_test::assembly_scene(false), o), std::invalid_argument);
}

TEST(VrmlWriter, VrmlNeedsAProtoForEveryNurbsNode) {
  bool has_curve = false;
  for (const auto& p : nurbs_protos()) has_curve = has_curve || p.name == "NurbsCurve";
  const Scene scene = vrml_test::single_shape_scene(vrml_test::semicircle_curve());
  if (has_curve) {
    EXPECT_NE(format_vrml(scene, with_encoding(VrmlEncoding::vrml97)).find("EXTERNPROTO NurbsCurve ["), std::string::npos);
  } else {
    try {
      format_vrml(scene, with_encoding(VrmlEncoding::vrml97));
      FAIL() << "VRML97 NurbsCurve written without a PROTO";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("no PROTO NurbsCurve"), std::string::npos) << e.what();
    }
  }
}

TEST(VrmlWriter, WritesAtomicallyAndReadsBack) {
  const auto path = (std::filesystem::temp_directory_path() / "cadnurbs_vrml_written.x3d").string();
  const Scene scene = vrml_test::assembly_scene(true);
  VrmlWriteOptions o = with_encoding(VrmlEncoding::x3d_xml);
  write_vrml(path, scene, o);
  EXPECT_EQ(read_file(path), format_vrml(scene, o));
  EXPECT_EQ(read_vrml(path).root.children.size(), 2u);
  std::filesystem::remove(path);
}

// The sizes of the test scenes, for the record (and a sanity check on what is written).
TEST(VrmlWriter, WrittenSizesOfTheTestScenes) {
  struct Named {
    const char* name;
    Scene scene;
  };
  TriangleMesh no_normals = vrml_test::octahedron_with_normals();
  no_normals.corner_normals.clear();
  const Named scenes[] = {
      {"quarter cylinder", vrml_test::single_shape_scene(TrimmedSurface{vrml_test::quarter_cylinder(), {}})},
      {"trimmed plate", vrml_test::single_shape_scene(vrml_test::trimmed_plate())},
      {"octahedron + normals", vrml_test::single_shape_scene(vrml_test::octahedron_with_normals())},
      {"octahedron", vrml_test::single_shape_scene(no_normals)},
      {"assembly (no curve)", vrml_test::assembly_scene(false)},
  };
  std::printf("%-22s %10s %10s %10s %10s\n", "scene", ".wrl", ".wrl self", ".x3dv", ".x3d");
  for (const auto& s : scenes) {
    VrmlWriteOptions self = with_encoding(VrmlEncoding::vrml97);
    self.self_contained = true;
    const size_t wrl = format_vrml(s.scene, with_encoding(VrmlEncoding::vrml97)).size();
    const size_t wrl_self = format_vrml(s.scene, self).size();
    const size_t x3dv = format_vrml(s.scene, with_encoding(VrmlEncoding::x3d_classic)).size();
    const size_t x3d = format_vrml(s.scene, with_encoding(VrmlEncoding::x3d_xml)).size();
    std::printf("%-22s %10zu %10zu %10zu %10zu\n", s.name, wrl, wrl_self, x3dv, x3d);
    EXPECT_GT(x3d, 0u);
    EXPECT_GE(wrl_self, wrl);
  }
}

}  // namespace
}  // namespace cadnurbs
