// Write each test scene in every encoding, read it back, compare within the writer's stated tolerances.
#include <gtest/gtest.h>

#include "formats/vrml/nurbs_protos.hpp"
#include "formats/vrml/vrml_reader.hpp"
#include "formats/vrml/vrml_writer.hpp"
#include "scene_comparison.hpp"
#include "test_scenes.hpp"

namespace cadnurbs {
namespace {

using vrml_test::expect_same_scene;

bool library_has(const std::string& name) {
  for (const auto& p : nurbs_protos())
    if (p.name == name) return true;
  return false;
}

struct Case {
  VrmlEncoding encoding;
  bool homogeneous;
};

// Without it GoogleTest prints the struct's bytes, padding included, into the test names.
void PrintTo(const Case& c, std::ostream* out) {
  *out << static_cast<int>(c.encoding) << (c.homogeneous ? " homogeneous" : " euclidean");
}

class RoundTrip : public ::testing::TestWithParam<Case> {
 protected:
  VrmlWriteOptions options() const {
    VrmlWriteOptions o;
    o.encoding = GetParam().encoding;
    o.homogeneous_control_points = GetParam().homogeneous;
    return o;
  }

  void round_trip(const Scene& scene, const VrmlWriteOptions& o) {
    const std::string text = format_vrml(scene, o);
    // The reader is told the opposite convention: the file's WorldInfo line must win.
    const Scene back = parse_vrml(text, "roundtrip", !o.homogeneous_control_points);
    SCOPED_TRACE(text.substr(0, 4000));
    expect_same_scene(scene, back, o);
  }
};

TEST_P(RoundTrip, RationalQuarterCylinder) {
  round_trip(vrml_test::single_shape_scene(TrimmedSurface{vrml_test::quarter_cylinder(), {}}), options());
}

TEST_P(RoundTrip, PlateTrimmedByCircleWithPolylineHole) {
  round_trip(vrml_test::single_shape_scene(vrml_test::trimmed_plate()), options());
}

TEST_P(RoundTrip, MeshWithNormals) {
  round_trip(vrml_test::single_shape_scene(vrml_test::octahedron_with_normals()), options());
}

TEST_P(RoundTrip, MeshWithoutNormals) {
  TriangleMesh mesh = vrml_test::octahedron_with_normals();
  mesh.corner_normals.clear();
  round_trip(vrml_test::single_shape_scene(mesh), options());
}

TEST_P(RoundTrip, TwoLevelTreeWithTransformsNamesAndColours) {
  // VRML97 has a 3D NurbsCurve only if the PROTO library implements one.
  const bool curve = GetParam().encoding != VrmlEncoding::vrml97 || library_has("NurbsCurve");
  round_trip(vrml_test::assembly_scene(curve), options());
}

TEST_P(RoundTrip, RationalSpaceCurve) {
  if (GetParam().encoding == VrmlEncoding::vrml97 && !library_has("NurbsCurve"))
    GTEST_SKIP() << "the NURBS PROTO library has no NurbsCurve";
  round_trip(vrml_test::single_shape_scene(vrml_test::semicircle_curve()), options());
}

TEST_P(RoundTrip, EmptySceneAndUnnamedColouredNodes) {
  round_trip(Scene{}, options());
  // An unnamed coloured node gets a generated DEF so its shapes can point at its colour; the name
  // comes back empty.
  Scene scene;
  scene.root.colour = Colour{0.5, 0.25, 1};
  SceneNode child;
  child.colour = Colour{0, 0, 0};
  child.shapes.push_back(Shape{"", TrimmedSurface{vrml_test::quarter_cylinder(), {}}, std::nullopt});
  child.shapes.push_back(Shape{"", vrml_test::octahedron_with_normals(), std::nullopt});
  scene.root.children.push_back(child);
  scene.root.shapes.push_back(Shape{"", vrml_test::octahedron_with_normals(), Colour{1, 1, 0}});
  scene.root.shapes.push_back(Shape{"", vrml_test::octahedron_with_normals(), std::nullopt});  // root's colour
  scene.unit = LengthUnit{"inch", 25.4};
  round_trip(scene, options());
}

TEST_P(RoundTrip, CoarseToleranceStillWithinIt) {
  VrmlWriteOptions o = options();
  o.coordinate_tolerance = 0.05;
  round_trip(vrml_test::assembly_scene(GetParam().encoding != VrmlEncoding::vrml97), o);
}

TEST_P(RoundTrip, FarFromOriginNeedsDoublePrecision) {
  Scene scene = vrml_test::single_shape_scene(TrimmedSurface{vrml_test::quarter_cylinder(), {}});
  scene.root.transform = Eigen::Translation3d(1e7, -3e6, 2e5);
  VrmlWriteOptions o = options();
  round_trip(scene, o);
  if (GetParam().encoding != VrmlEncoding::vrml97) {
    // The control points themselves are small; only the translation is large: Coordinate suffices.
    EXPECT_EQ(format_vrml(scene, o).find("CoordinateDouble"), std::string::npos);
    Scene far = vrml_test::single_shape_scene(TrimmedSurface{vrml_test::quarter_cylinder(), {}});
    for (auto& p : std::get<TrimmedSurface>(far.root.shapes[0].geometry).surface.points) p += Eigen::Vector3d(1e7, 0, 0);
    EXPECT_NE(format_vrml(far, o).find("CoordinateDouble"), std::string::npos);
    round_trip(far, o);
  }
}

std::string case_name(const ::testing::TestParamInfo<Case>& info) {
  const char* encodings[] = {"vrml97", "x3d_classic", "x3d_xml"};
  return std::string(encodings[static_cast<int>(info.param.encoding)]) +
         (info.param.homogeneous ? "_homogeneous" : "_euclidean");
}

INSTANTIATE_TEST_SUITE_P(Encodings, RoundTrip,
                         ::testing::Values(Case{VrmlEncoding::vrml97, true}, Case{VrmlEncoding::vrml97, false},
                                           Case{VrmlEncoding::x3d_classic, true},
                                           Case{VrmlEncoding::x3d_classic, false}, Case{VrmlEncoding::x3d_xml, true},
                                           Case{VrmlEncoding::x3d_xml, false}),
                         case_name);

}  // namespace
}  // namespace cadnurbs
