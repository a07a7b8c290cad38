// Files written by other programs (shared/corpus/vrml): the simple NURBS ones read, with their counts
// taken by hand from the file text; the others are refused with one line naming node and line.
#include <gtest/gtest.h>

#include <cmath>

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

// Files outside the subset: one line, the file, the line and the node.
void expect_refused(const std::string& file, const std::string& message) {
  try {
    read_vrml(corpus + file);
    FAIL() << file << " was read";
  } catch (const FileError& e) {
    EXPECT_EQ(std::string(e.what()), corpus + file + ": " + message);
  }
}

TEST(VrmlCorpus, FilesOutsideTheSubsetAreRefusedByNodeAndLine) {
  // testall.wrl: everything up to line 325 is inside the subset (EXTERNPROTOs skipped, NurbsGroup read as
  // a group); "CoordinateDeformer" at line 325 is not.
  expect_refused("testall.wrl", "line 325: unsupported node CoordinateDeformer (outside the VRML97 subset cadnurbs reads)");
  expect_refused("fish.wrl", "line 278: unsupported node CoordinateInterpolator (outside the VRML97 subset cadnurbs reads)");
}

TEST(VrmlCorpus, LargeFilesFailFastWithOneLine) {
  // The robots texture their shapes (Appearance.texture, outside the subset) long before their PROTOs.
  expect_refused("robot_jme2.x3dv", "line 135: Appearance has no field texture in the subset cadnurbs reads");
  expect_refused("robot_opengl.x3dv", "line 359: Appearance has no field texture in the subset cadnurbs reads");
}

}  // namespace
}  // namespace cadnurbs
