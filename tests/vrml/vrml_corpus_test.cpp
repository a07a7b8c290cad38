// Files written by other programs (shared/corpus/vrml), read with their counts taken by hand from the
// file text.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/bounding_box.hpp"
#include "formats/common/file_io.hpp"
#include "formats/vrml/vrml_reader.hpp"

namespace cadnurbs {
namespace {

const std::string corpus = std::string(CADNURBS_SHARED_DIR) + "/corpus/vrml/";

TEST(VrmlCorpus, H3dNurbsPatchSurface) {
  // NurbsPatchSurface.x3d (H3DAPI): one NurbsPatchSurface, uDimension 4 x vDimension 4 = 16 points, no
  // knots (clamped uniform), weight 1.6 at index 6; an IndexedLineSet draws the control net: coordIndex
  // "0 1 2 3 -1 ... 3 7 11 15" = 8 polylines of 4 points, read as 8 order-2 curves.
  const Scene scene = read_vrml(corpus + "NurbsPatchSurface.x3d");
  const SceneCounts c = count_entities(scene);
  EXPECT_EQ(c.surfaces, 1);
  EXPECT_EQ(c.curves, 8);
  EXPECT_EQ(c.control_points, 16 + 8 * 4);
  ASSERT_EQ(scene.root.shapes.size(), 9u);
  EXPECT_EQ(scene.root.shapes[0].colour, (Colour{0.6, 0.6, 0.6}));  // emissiveColor of the lines
  const auto& surface = std::get<TrimmedSurface>(scene.root.shapes[8].geometry).surface;
  EXPECT_EQ(scene.root.shapes[8].colour, (Colour{1, 0, 0}));
  EXPECT_EQ(surface.u_knots, (std::vector<double>{0, 0, 0, 0.5, 1, 1, 1}));
  // Homogeneous: point 6 is (0.1 0.1 0.2) / 1.6.
  EXPECT_DOUBLE_EQ(surface.weights[6], 1.6);
  EXPECT_LE((surface.points[6] - Eigen::Vector3d(0.0625, 0.0625, 0.125)).norm(), 1e-15);
}

TEST(VrmlCorpus, H3dNurbsTrimmedSurface) {
  // NurbsTrimmedSurface.x3d (H3DAPI): 4 x 4 = 16 points; two Contour2D: a NurbsCurve2D of 5 points
  // (order 2), and ContourPolyline2D (2 points) + NurbsCurve2D (3 points, order 3 by default) +
  // ContourPolyline2D (2 points): 12 trim control points.
  const Scene scene = read_vrml(corpus + "NurbsTrimmedSurface.x3d");
  const SceneCounts c = count_entities(scene);
  EXPECT_EQ(c.surfaces, 1);
  EXPECT_EQ(c.trimmed_surfaces, 1);
  EXPECT_EQ(c.control_points, 16);
  EXPECT_EQ(c.trim_loops, 2);
  EXPECT_EQ(c.trim_control_points, 5 + 2 + 3 + 2);
  const auto& trimmed = std::get<TrimmedSurface>(scene.root.shapes.at(0).geometry);
  EXPECT_EQ(std::get<NurbsCurve>(trimmed.loops[1].segments[1]).knots, (std::vector<double>{1, 1, 1, 3, 3, 3}));
}

TEST(VrmlCorpus, CastleNurbsWeights) {
  // nurbs_weights.x3dv (castle-engine demo models): two NurbsCurves of 5 points (order 3, weights
  // 1 0.25 1 1 1, no knots), one NurbsPatchSurface of 5 x 2 = 10 points, and a Box shape DEF'd in one
  // Transform and USE'd in another: two meshes of 8 vertices and 12 triangles.
  const Scene scene = read_vrml(corpus + "nurbs_weights.x3dv");
  const SceneCounts c = count_entities(scene);
  EXPECT_EQ(c.surfaces, 1);
  EXPECT_EQ(c.curves, 2);
  EXPECT_EQ(c.meshes, 2);
  EXPECT_EQ(c.control_points, 5 + 5 + 10);
  EXPECT_EQ(c.mesh_vertices, 16);
  EXPECT_EQ(c.mesh_triangles, 24);
  ASSERT_EQ(scene.root.shapes.size(), 3u);
  ASSERT_EQ(scene.root.children.size(), 2u);
  EXPECT_EQ(scene.root.children[0].transform.translation(), Eigen::Vector3d(-2.5, 5, 0));
  EXPECT_EQ(scene.root.children[1].shapes.at(0).name, "S");
  // The file's own comment: dividing the control point by 4 "makes weight 1/4 behave intuitive", i.e.
  // control points are homogeneous. Read so, the second curve's point is (-2.5, 5, 2).
  const auto& second = std::get<NurbsCurve>(scene.root.shapes[1].geometry);
  EXPECT_LE((second.points[1] - Eigen::Vector3d(-2.5, 5, 2)).norm(), 1e-15);
  const Scene euclidean = read_vrml(corpus + "nurbs_weights.x3dv", false);
  EXPECT_LE((std::get<NurbsCurve>(euclidean.root.shapes[1].geometry).points[1] - Eigen::Vector3d(-0.625, 1.25, 0.5)).norm(),
            1e-15);
}

TEST(VrmlCorpus, WhiteDunePrimitives) {
  // nurbs_dune_primitives.x3dv (white_dune): five NurbsPatchSurface, 4x4, 13x9, 9x5, 9x6, 9x7 points
  // (16 + 117 + 45 + 54 + 63 = 295, matching the point lists), under four top-level Transforms (the
  // third holds the fourth surface's Transform as a child).
  const Scene scene = read_vrml(corpus + "nurbs_dune_primitives.x3dv");
  const SceneCounts c = count_entities(scene);
  EXPECT_EQ(c.surfaces, 5);
  EXPECT_EQ(c.control_points, 295);
  ASSERT_EQ(scene.root.children.size(), 4u);
  EXPECT_EQ(scene.root.children[2].children.size(), 1u);
}

TEST(VrmlCorpus, WhiteDuneDoor) {
  // door.x3dv (white_dune): two NurbsTrimmedSurface, 4 x 8 = 32 and 17 x 9 = 153 points. The first has
  // two Contour2D (a closed ContourPolyline2D of 5 points, a NurbsCurve2D of 9), the second one
  // (a NurbsCurve2D of 9 points, order 4). Read as written: the loops that leave the domains are cut
  // to them when the file is loaded (converters' Cli test).
  const Scene scene = read_vrml(corpus + "door.x3dv");
  const SceneCounts c = count_entities(scene);
  EXPECT_EQ(c.surfaces, 2);
  EXPECT_EQ(c.trimmed_surfaces, 2);
  EXPECT_EQ(c.control_points, 32 + 153);
  EXPECT_EQ(c.trim_loops, 3);
  EXPECT_EQ(c.trim_control_points, 5 + 9 + 9);
}

// Whole scenes from white_dune: read at rest; what has no place in a Scene is named, one note per kind.
SceneFromNodes read_whole(const std::string& file) { return read_vrml_scene(corpus + file); }

bool has_note(const SceneFromNodes& read, const std::string& note) {
  return std::find(read.notes.begin(), read.notes.end(), note) != read.notes.end();
}

TEST(VrmlCorpus, WhiteDuneFishIsReadAtTheFirstFrameOfItsAnimation) {
  // fish.wrl: 3 NurbsSurface (9 x 6 = 54, 4 x 4, 4 x 4 points) and 4 Spheres (eyes), each read as the
  // exact 9 x 5 rational sphere. Each NurbsSurface's controlPoint is replaced on every frame by a
  // CoordinateInterpolator a looping TimeSensor drives; the file's own first control point of the body
  // is 1075711066505216 (line 89). At rest it is the first key set: (0 0 -2.564630), and the fish
  // stays within a few units.
  const SceneFromNodes read = read_whole("fish.wrl");
  const SceneCounts c = count_entities(read.scene);
  EXPECT_EQ(c.surfaces, 7);
  EXPECT_EQ(c.control_points, 54 + 16 + 16 + 4 * 45);
  const Shape* body = nullptr;
  for_each_shape(read.scene, [&](const Shape& shape, const Eigen::Affine3d&, const Colour&) {
    if (std::get<TrimmedSurface>(shape.geometry).surface.points.size() == 54) body = &shape;
  });
  ASSERT_NE(body, nullptr);
  const auto& surface = std::get<TrimmedSurface>(body->geometry).surface;
  EXPECT_LE((surface.points[0] - Eigen::Vector3d(0, 0, -2.564630)).norm(), 1e-12);
  EXPECT_LT(scene_bounding_box(read.scene).diagonal().norm(), 20.0);
  EXPECT_EQ(read.notes, (std::vector<std::string>{
                            "3 CoordinateInterpolator routed to NurbsSurface.controlPoint: taken at the first key of its looping animation (fraction 0)",
                            "3 CoordinateInterpolator left out: animation and interaction are not converted: the scene is taken at rest",
                            "3 TimeSensor left out: animation and interaction are not converted: the scene is taken at rest",
                            "1 CurveAnimation (PROTO) left out: its EXTERNPROTO's urls name no local file that declares it: not expanded",
                            "9 ROUTE left out: animation and interaction are not converted: the scene is taken at rest"}));
}

TEST(VrmlCorpus, WhiteDuneTestallReadsEveryAmendmentNode) {
  // testall.wrl: a NurbsCurve of 5 points; a NurbsGroup holding a 4 x 4 NurbsSurface; a TrimmedSurface
  // (4 x 4) whose one Contour2D holds an empty NurbsCurve2D and an empty Polyline2D: it trims nothing. An
  // empty CoordinateDeformer (deforms nothing, holds nothing), an empty NurbsPositionInterpolator and an
  // InlineLoadControl of a file that is not there.
  const SceneFromNodes read = read_whole("testall.wrl");
  const SceneCounts c = count_entities(read.scene);
  EXPECT_EQ(c.curves, 1);
  EXPECT_EQ(c.surfaces, 2);
  EXPECT_EQ(c.trim_loops, 0);
  EXPECT_EQ(c.control_points, 5 + 16 + 16);
  EXPECT_EQ(read.notes, (std::vector<std::string>{
                            "1 NurbsPositionInterpolator left out: animation and interaction are not converted: the scene is taken at rest",
                            "1 InlineLoadControl \"NurbsSurface_example.wrl\" left out: not a local file: not followed"}));
}

TEST(VrmlCorpus, WhiteDuneRobotsAreReadWhole) {
  // robot_jme2.x3dv: 19 NurbsPatchSurface and 11 Spheres in the text; the LOD's second level is a
  // Sphere, and the first (most detailed) level is the one read: 19 + 10 surfaces.
  const SceneFromNodes jme2 = read_whole("robot_jme2.x3dv");
  EXPECT_EQ(count_entities(jme2.scene).surfaces, 29);
  EXPECT_TRUE(has_note(jme2, "4 CoordinateInterpolator routed to Coordinate.point: taken at the first key of its looping animation (fraction 0)"));
  EXPECT_TRUE(has_note(jme2, "3 Text left out: geometry without a NURBS or mesh form in cadnurbs"));
  EXPECT_TRUE(has_note(jme2, "1 SuperShape (PROTO) left out: its EXTERNPROTO's urls name no local file that declares it: not expanded"));
  EXPECT_TRUE(has_note(jme2, "40 ROUTE left out: animation and interaction are not converted: the scene is taken at rest"));
  // robot_opengl.x3dv (HAnim, Switches, Scripts): 27 NurbsPatchSurface and 11 Spheres in the text; 4
  // NurbsPatchSurface lie under the Transform of line 12540, scaled 0 0 0 (the animation grows it):
  // 27 + 11 - 4.
  const SceneFromNodes opengl = read_whole("robot_opengl.x3dv");
  EXPECT_EQ(count_entities(opengl.scene).surfaces, 34);
  EXPECT_TRUE(has_note(opengl, "1 Transform scaled to nothing left out: it draws nothing at rest; its children are left out with it"));
  EXPECT_TRUE(has_note(opengl, "4 Script left out: animation and interaction are not converted: the scene is taken at rest"));
  EXPECT_TRUE(has_note(opengl, "86 ROUTE left out: animation and interaction are not converted: the scene is taken at rest"));
}

}  // namespace
}  // namespace cadnurbs
