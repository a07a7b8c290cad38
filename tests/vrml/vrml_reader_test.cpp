// The reader on hand-written text: defaults, conventions, and one-line errors that name the line.
#include <gtest/gtest.h>

#include "formats/common/file_io.hpp"
#include "formats/common/gzip.hpp"
#include "formats/vrml/vrml_reader.hpp"

namespace cadnurbs {
namespace {

// The FileError message of parsing `text`, or "" when it parses.
std::string error_of(const std::string& text) {
  try {
    parse_vrml(text, "t.x3dv");
  } catch (const FileError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "not one line: " << e.what();
    return e.what();
  }
  return "";
}

const std::string x3d_header = "#X3D V3.3 utf8\nPROFILE Interchange\n";

TEST(VrmlReader, ClassicWithCommentsCommasAndDefaults) {
  const Scene scene = parse_vrml(x3d_header +
                                     "# a comment\n"
                                     "Shape { geometry NurbsPatchSurface {  # trailing comment\n"
                                     "  uDimension 3, vDimension 2 uOrder 2 vOrder 2\n"
                                     "  controlPoint Coordinate { point [ 0 0 0, 1 0 0, 2 0 0,\n"
                                     "                                    0 1 0, 1 1 0, 2 1 +1e0, ] }\n"
                                     "} }\n",
                                 "t.x3dv");
  ASSERT_EQ(scene.root.shapes.size(), 1u);
  const auto& s = std::get<TrimmedSurface>(scene.root.shapes[0].geometry).surface;
  // Absent knots: the clamped uniform vector on [0, 1].
  EXPECT_EQ(s.u_knots, (std::vector<double>{0, 0, 0.5, 1, 1}));
  EXPECT_EQ(s.v_knots, (std::vector<double>{0, 0, 1, 1}));
  EXPECT_TRUE(s.weights.empty());
  EXPECT_EQ(s.points[5], Eigen::Vector3d(2, 1, 1));
  EXPECT_FALSE(scene.root.shapes[0].colour.has_value());
  EXPECT_EQ(scene.unit.name, "mm");
}

TEST(VrmlReader, WorldInfoGivesUnitAndConvention) {
  const std::string body =
      "Shape { geometry NurbsCurve { order 2 knot [0 0 1 1] weight [2 4]\n"
      "  controlPoint Coordinate { point [2 2 2 4 4 4] } } }\n";
  const Scene inch = parse_vrml(x3d_header + "WorldInfo { info [\"unit inch\" \"controlPoint euclidean\"] }\n" + body, "t");
  EXPECT_EQ(inch.unit.name, "inch");
  EXPECT_DOUBLE_EQ(inch.unit.millimetres, 25.4);
  EXPECT_EQ(inch.source_unit.name, "inch");
  EXPECT_EQ(std::get<NurbsCurve>(inch.root.shapes[0].geometry).points[1], Eigen::Vector3d(4, 4, 4));
  const Scene homogeneous = parse_vrml(x3d_header + "WorldInfo { info \"unit furlong 201168\" }\n" + body, "t");
  EXPECT_DOUBLE_EQ(homogeneous.unit.millimetres, 201168);
  EXPECT_EQ(std::get<NurbsCurve>(homogeneous.root.shapes[0].geometry).points[1], Eigen::Vector3d(1, 1, 1));
  EXPECT_EQ(error_of(x3d_header + "WorldInfo { info \"unit furlong\" }\n" + body),
            "t.x3dv: line 3: WorldInfo: info \"unit furlong\": unknown unit without a size in millimetres");
}

TEST(VrmlReader, ParseErrorsNameTheLine) {
  EXPECT_EQ(error_of("#VRML V1.0 ascii\n"),
            "t.x3dv: line 1: not a VRML97 (#VRML V2.0 utf8) or X3D classic (#X3D V3.x utf8) header");
  EXPECT_EQ(error_of(x3d_header + "\n\nTransform { children [\n  Shape { geometry Spere { } }\n] }\n"),
            "t.x3dv: line 6: unknown node Spere (neither a X3D node nor a PROTO declared before it)");
  EXPECT_EQ(error_of(x3d_header + "Transform {\n  translation 1 2\n}\n"),
            "t.x3dv: line 5: field translation: expected a number, found '}'");
  EXPECT_EQ(error_of(x3d_header + "Transform {\n  translate 1 2 3\n}\n"),
            "t.x3dv: line 4: Transform has no field translate");
  EXPECT_EQ(error_of(x3d_header + "Shape {\n geometry USE Nowhere\n}\n"),
            "t.x3dv: line 4: USE Nowhere before any DEF Nowhere");
  EXPECT_EQ(error_of(x3d_header + "Group {\n children [\n"), "t.x3dv: line 4: field children: '[' is never closed");
  EXPECT_EQ(error_of(x3d_header + "Transform { scale 1 x 1 }\n"),
            "t.x3dv: line 3: field scale: expected a number, found 'x'");
  EXPECT_EQ(error_of(x3d_header + "ROUTE a.b FROM c.d\n"), "t.x3dv: line 3: expected TO in a ROUTE, found 'FROM'");
  EXPECT_EQ(error_of(x3d_header + "ROUTE ab TO c.d\n"), "t.x3dv: line 3: expected a ROUTE's source as NAME.FIELD, found 'ab'");
  EXPECT_EQ(error_of(x3d_header + "UNIT length km 1000\n"),
            "t.x3dv: line 3: UNIT statements are not read: they change the units of the numbers");
  EXPECT_EQ(error_of(x3d_header + "TimeSensor { fraction_changed 0.5 }\n"),
            "t.x3dv: line 3: field fraction_changed of TimeSensor is an event: it has no value");
  EXPECT_EQ(error_of(x3d_header + "WorldInfo { title \"open\n\n"), "t.x3dv: line 3: string is not terminated");
  EXPECT_EQ(error_of("#VRML V2.0 utf8\nShape { geometry NurbsPatchSurface {} }\n"),
            "t.x3dv: line 2: unknown node NurbsPatchSurface (neither a VRML97 node nor a PROTO declared before it)");
}

TEST(VrmlReader, GeometryErrorsNameTheNodeAndLine) {
  EXPECT_EQ(error_of(x3d_header + "Shape { geometry\n NurbsCurve { order 2 knot [0 0 1]\n"
                                  " controlPoint Coordinate { point [0 0 0 1 1 1] } } }\n"),
            "t.x3dv: line 4: NurbsCurve: knot has 3 values; 2 control points of order 2 need 4");
  EXPECT_EQ(error_of(x3d_header + "Shape { geometry\n NurbsCurve { order 2 knot [0 1 0.5 1]\n"
                                  " controlPoint Coordinate { point [0 0 0 1 1 1] } } }\n")
                .rfind("t.x3dv: line 4: NurbsCurve: ", 0),
            0u);
  EXPECT_EQ(error_of(x3d_header + "Shape { geometry NurbsPatchSurface {\n uDimension 2 vDimension 2 uOrder 2 vOrder 2\n"
                                  " controlPoint Coordinate { point [0 0 0 1 0 0 0 1 0] } } }\n"),
            "t.x3dv: line 3: NurbsPatchSurface: 3 control points, but uDimension x vDimension = 2 x 2");
  EXPECT_EQ(error_of(x3d_header + "Shape { geometry IndexedFaceSet {\n coord Coordinate { point [0 0 0 1 0 0 0 1 0] }\n"
                                  " coordIndex [0 1 3 -1] } }\n")
                .rfind("t.x3dv: line 3: IndexedFaceSet: ", 0),
            0u);
  EXPECT_EQ(error_of(x3d_header + "Shape { geometry NurbsTrimmedSurface {\n uDimension 2 vDimension 2 uOrder 2 vOrder 2\n"
                                  " controlPoint Coordinate { point [0 0 0 1 0 0 0 1 0 1 1 0] }\n"
                                  " trimmingContour Contour2D { children ContourPolyline2D { controlPoint [.1 .1 .9 .1 .5 .9] } }\n"
                                  "} }\n"),
            "t.x3dv: line 3: NurbsTrimmedSurface loop 0: does not close: gap 0.894427 between segments");
}

TEST(VrmlReader, XmlErrorsNameTheLine) {
  EXPECT_EQ(error_of("<?xml version='1.0'?>\n<X3D>\n<Scene>\n<Shape>\n<Spere/>\n</Shape>\n</Scene>\n</X3D>\n"),
            "t.x3dv: line 5: unknown node Spere (not an X3D node; a PROTO is used by <ProtoInstance>)");
  EXPECT_EQ(error_of("<X3D>\n<Scene>\n<ProtoInstance name='P'/>\n</Scene>\n</X3D>\n"),
            "t.x3dv: line 3: ProtoInstance of P before its declaration");
  EXPECT_EQ(error_of("<X3D>\n<head><unit category='length' name='km' conversionFactor='1000'/></head>\n</X3D>\n"),
            "t.x3dv: line 2: <unit> statements are not read: they change the units of the numbers");
  EXPECT_EQ(error_of("<X3D>\n<Scene>\n<Transform translation='1 2'/>\n</Scene>\n</X3D>\n"),
            "t.x3dv: line 3: field translation needs 3 numbers");
  EXPECT_EQ(error_of("<X3D>\n<Scene>\n<Group>\n</Scene>\n</X3D>\n"), "t.x3dv: line 4: </Scene> closes <Group> of line 3");
  EXPECT_EQ(error_of("<X3D>\n<Scene>\n<Group>\n"), "t.x3dv: line 3: element <Group> is never closed");
  EXPECT_EQ(error_of("<html>\n</html>\n"), "t.x3dv: line 1: the root element is <html>, not <X3D>");
  EXPECT_EQ(error_of("<X3D><Scene>\n<Transform\n  scale='1 &bogus; 1'/></Scene></X3D>"),
            "t.x3dv: line 3: unknown entity &bogus;");
}

TEST(VrmlReader, XmlEntitiesContainerFieldsAndUse) {
  const Scene scene = parse_vrml(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<!DOCTYPE X3D PUBLIC \"x\" \"y\">\n<!-- c -->\n"
      "<X3D profile='Interchange' version='3.3'><head><meta name='a' content='b'/></head><Scene>\n"
      "<WorldInfo info='\"name a_b A&apos;s &amp; &#x42;\"'/>\n"
      "<Transform DEF=\"a_b\" translation='1,2,3'>\n"
      " <Shape><Appearance><Material diffuseColor='1 0 0'/></Appearance>\n"
      "  <IndexedFaceSet coordIndex='0 1 2 3'><Coordinate DEF='C' point='0 0 0 1 0 0 1 1 0 0 1 0'/></IndexedFaceSet>\n"
      " </Shape>\n"
      " <Shape><IndexedFaceSet coordIndex='0 2 1 -1'><Coordinate USE='C'/></IndexedFaceSet></Shape>\n"
      "</Transform>\n</Scene></X3D>\n",
      "t.x3d");
  EXPECT_EQ(scene.root.name, "A's & B");
  EXPECT_EQ(scene.root.transform.translation(), Eigen::Vector3d(1, 2, 3));
  ASSERT_EQ(scene.root.shapes.size(), 2u);
  EXPECT_EQ(scene.root.shapes[0].colour, (Colour{1, 0, 0}));
  // The quad is fanned into two triangles; the USE'd coordinates are shared.
  EXPECT_EQ(std::get<TriangleMesh>(scene.root.shapes[0].geometry).triangles.size(), 2u);
  EXPECT_EQ(std::get<TriangleMesh>(scene.root.shapes[1].geometry).positions.size(), 4u);
}

TEST(VrmlReader, ReadsGzippedText) {
  const std::string text =
      "#X3D V3.3 utf8\nPROFILE Interchange\nDEF Box_part Transform { translation 1 2 3 children [\n"
      " Shape { geometry IndexedFaceSet { coordIndex [0 1 2 -1] coord Coordinate { point [0 0 0 1 0 0 0 1 0] } } }\n"
      "] }\n";
  const Scene scene = parse_vrml(gzip(text), "t.x3dvz");
  EXPECT_EQ(scene.root.name, "Box_part");
  EXPECT_EQ(scene.root.transform.translation(), Eigen::Vector3d(1, 2, 3));
  ASSERT_EQ(scene.root.shapes.size(), 1u);
  EXPECT_EQ(std::get<TriangleMesh>(scene.root.shapes[0].geometry).triangles.size(), 1u);
}

TEST(VrmlReader, RefusesDamagedGzipData) {
  EXPECT_EQ(error_of(std::string("\x1f\x8b\x08\x00", 4)), "t.x3dv: damaged or truncated gzip data");
  const std::string packed = gzip("#X3D V3.3 utf8\nGroup {}\n");
  EXPECT_EQ(error_of(packed.substr(0, packed.size() - 6)), "t.x3dv: damaged or truncated gzip data");
}

}  // namespace
}  // namespace cadnurbs
