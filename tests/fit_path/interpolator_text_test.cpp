// formats/vrml: interpolators found in VRML/X3D text with their exact bytes, and the NURBS node text and
// declarations that replace them.
#include <gtest/gtest.h>

#include "formats/common/file_io.hpp"
#include "formats/vrml/interpolators_in_text.hpp"
#include "formats/vrml/nurbs_interpolator_text.hpp"

namespace cadnurbs::test {
namespace {

std::string bytes_of(const std::string& text, const InterpolatorInText& node) {
  return text.substr(node.begin, node.end - node.begin);
}

TEST(InterpolatorsInText, ClassicNodesWithTheirDefNamesAndExactBytes) {
  const std::string text =
      "#VRML V2.0 utf8\n"
      "# PositionInterpolator { key [ 9 ] } in a comment is not a node\n"
      "WorldInfo { info \"PositionInterpolator { key [ 8 ] }\" }\n"
      "DEF Mover Transform { children [\n"
      "  DEF PATH PositionInterpolator { key [ 0, .5 1 ] keyValue [ 0 0 0, 1 2 3, +4 5 6e-1 ] }\n"
      "  OrientationInterpolator{key 0 keyValue 0 0 1 1.5}\n"
      "] }\n"
      "PROTO Moving [ field MFFloat k [] ] { PositionInterpolator { key IS k keyValue [ 1 1 1 ] } }\n"
      "DEF M PositionInterpolator { metadata MetadataString { value [ \"x\" ] } key [ 0 1 ] keyValue [ 0 0 0 1 1 1 ] }\n"
      "ROUTE PATH.value_changed TO Mover.set_translation\n";
  const auto nodes = find_interpolators(text, false, "t.wrl");
  ASSERT_EQ(nodes.size(), 4u);
  EXPECT_EQ(nodes[0].type, "PositionInterpolator");
  EXPECT_EQ(nodes[0].def_name, "PATH");
  EXPECT_EQ(nodes[0].line, 5);
  EXPECT_EQ(bytes_of(text, nodes[0]),
            "DEF PATH PositionInterpolator { key [ 0, .5 1 ] keyValue [ 0 0 0, 1 2 3, +4 5 6e-1 ] }");
  EXPECT_EQ(nodes[0].key, (std::vector<double>{0, 0.5, 1}));
  EXPECT_EQ(nodes[0].key_value, (std::vector<double>{0, 0, 0, 1, 2, 3, 4, 5, 0.6}));
  EXPECT_EQ(nodes[0].unconvertible, "");
  EXPECT_EQ(nodes[1].type, "OrientationInterpolator");
  EXPECT_EQ(nodes[1].def_name, "");
  EXPECT_EQ(bytes_of(text, nodes[1]), "OrientationInterpolator{key 0 keyValue 0 0 1 1.5}");
  EXPECT_EQ(nodes[1].key_value, (std::vector<double>{0, 0, 1, 1.5}));
  EXPECT_EQ(nodes[2].unconvertible, "its field key is given by IS");
  EXPECT_EQ(nodes[3].unconvertible, "it has a field metadata");
  EXPECT_EQ(nodes[3].key, (std::vector<double>{0, 1}));
}

TEST(InterpolatorsInText, ClassicKeysThatAreNotNumbersAreAnErrorNamingTheLine) {
  try {
    find_interpolators("#VRML V2.0 utf8\nPositionInterpolator {\n key [ 0 TRUE ] }\n", false, "t.wrl");
    FAIL() << "accepted";
  } catch (const FileError& e) {
    EXPECT_STREQ(e.what(), "t.wrl: line 3: key holds 'TRUE', not a number");
  }
}

TEST(InterpolatorsInText, XmlElementsWithUsesAndChildren) {
  const std::string text =
      "<?xml version='1.0'?>\n<X3D profile='Interchange' version='3.3'><Scene>\n"
      "<PositionInterpolator DEF='P' key='0 1' keyValue='0 0 0, 1 1 1'/>\n"
      "<Group><PositionInterpolator USE='P'/></Group>\n"
      "<PositionInterpolator DEF='Q' key='0 1' keyValue='0 0 0 1 1 1'><MetadataString/></PositionInterpolator>\n"
      "</Scene></X3D>\n";
  const auto nodes = find_interpolators(text, true, "t.x3d");
  ASSERT_EQ(nodes.size(), 3u);
  EXPECT_EQ(bytes_of(text, nodes[0]), "<PositionInterpolator DEF='P' key='0 1' keyValue='0 0 0, 1 1 1'/>");
  EXPECT_EQ(nodes[0].key_value.size(), 6u);
  EXPECT_EQ(nodes[1].use_name, "P");
  EXPECT_EQ(bytes_of(text, nodes[1]), "<PositionInterpolator USE='P'/>");
  EXPECT_EQ(nodes[2].unconvertible, "it has a child element <MetadataString>");
  EXPECT_EQ(bytes_of(text, nodes[2]).substr(0, 30), "<PositionInterpolator DEF='Q' ");
  EXPECT_EQ(text.substr(nodes[2].end - 23, 23), "</PositionInterpolator>");
}

NurbsCurve small_cubic() {
  NurbsCurve c;
  c.order = 4;
  c.knots = {0, 0, 0, 0, 0.5, 1, 1, 1, 1};
  c.points = {{0, 0, 0}, {1, 2, 0}, {2, 2, 0}, {3, 0, 1.25}, {4, 0, 0}};
  return c;
}

TEST(NurbsInterpolatorText, TheNodeInEachEncoding) {
  const NurbsTolerances tolerances{1e-3, 0, 1e-6};
  EXPECT_EQ(nurbs_position_interpolator_text(small_cubic(), "P", VrmlEncoding::vrml97, tolerances),
            "DEF P NurbsPositionInterpolator{dimension 5 order 4 knot[0 0 0 0 .5 1 1 1 1] "
            "keyValue[0 0 0\n1 2 0\n2 2 0\n3 0 1.25\n4 0 0]}");
  EXPECT_EQ(nurbs_position_interpolator_text(small_cubic(), "", VrmlEncoding::x3d_classic, tolerances),
            "NurbsPositionInterpolator{order 4 knot[0 0 0 0 .5 1 1 1 1] "
            "controlPoint Coordinate{point[0 0 0\n1 2 0\n2 2 0\n3 0 1.25\n4 0 0]}}");
  EXPECT_EQ(nurbs_position_interpolator_text(small_cubic(), "A&B", VrmlEncoding::x3d_xml, tolerances, "children"),
            "<NurbsPositionInterpolator DEF='A&amp;B' containerField='children' order='4' knot='0 0 0 0 .5 1 1 1 1'>"
            "<Coordinate containerField='controlPoint' point='0 0 0\n1 2 0\n2 2 0\n3 0 1.25\n4 0 0'/>"
            "</NurbsPositionInterpolator>");
  NurbsCurve rational = small_cubic();
  rational.weights.assign(5, 1.0);
  EXPECT_THROW(nurbs_position_interpolator_text(rational, "", VrmlEncoding::vrml97, tolerances), std::invalid_argument);
}

TEST(NurbsInterpolatorText, AsWrittenRoundsLikeTheText) {
  NurbsCurve c = small_cubic();
  c.points[1] = {1.00012345, 2.0004, 0};
  c.knots[4] = 0.50000012;
  const NurbsCurve written = as_written(c, NurbsTolerances{1e-3, 0, 1e-6});
  EXPECT_EQ(written.points[1], Eigen::Vector3d(1, 2, 0));
  EXPECT_EQ(written.knots[4], 0.5);
}

TEST(NurbsInterpolatorText, DeclarationsAreAddedOnceWhereEachEncodingWantsThem) {
  const std::string vrml = "#VRML V2.0 utf8\nGroup {}\n";
  const std::string declared = with_nurbs_interpolator_declared(vrml, VrmlEncoding::vrml97, "protos.wrl");
  EXPECT_EQ(declared.rfind("#VRML V2.0 utf8\nEXTERNPROTO NurbsPositionInterpolator [\n eventIn SFFloat set_fraction\n", 0), 0u)
      << declared;
  EXPECT_NE(declared.find("\"urn:inet:blaxxun.com:node:NurbsPositionInterpolator\" "
                          "\"protos.wrl#NurbsPositionInterpolator\"]\nGroup {}\n"),
            std::string::npos)
      << declared;
  EXPECT_EQ(with_nurbs_interpolator_declared(declared, VrmlEncoding::vrml97, "protos.wrl"), declared);

  EXPECT_EQ(with_nurbs_interpolator_declared("#X3D V3.3 utf8\nPROFILE Interchange\nGroup {}\n", VrmlEncoding::x3d_classic, ""),
            "#X3D V3.3 utf8\nPROFILE Interchange\nCOMPONENT NURBS:1\nGroup {}\n");
  for (const std::string unchanged : {"#X3D V3.3 utf8\nPROFILE Full\nGroup {}\n",
                                      "#X3D V3.3 utf8\nPROFILE Immersive\nCOMPONENT NURBS:4\nGroup {}\n"})
    EXPECT_EQ(with_nurbs_interpolator_declared(unchanged, VrmlEncoding::x3d_classic, ""), unchanged);

  EXPECT_EQ(with_nurbs_interpolator_declared("<X3D profile='Interchange'><head>\n<meta name='a' content='b'/></head><Scene/></X3D>",
                                             VrmlEncoding::x3d_xml, ""),
            "<X3D profile='Interchange'><head>\n<component name='NURBS' level='1'/>\n<meta name='a' content='b'/></head><Scene/></X3D>");
  EXPECT_EQ(with_nurbs_interpolator_declared("<X3D profile='Interchange' a='>'><Scene/></X3D>", VrmlEncoding::x3d_xml, ""),
            "<X3D profile='Interchange' a='>'>\n<head><component name='NURBS' level='1'/></head><Scene/></X3D>");
  EXPECT_EQ(with_nurbs_interpolator_declared("<X3D><head/><Scene/></X3D>", VrmlEncoding::x3d_xml, ""),
            "<X3D><head><component name='NURBS' level='1'/></head><Scene/></X3D>");
}

}  // namespace
}  // namespace cadnurbs::test
