// Sewing (analysis/sewing/sew_faces): edges recovered from geometry make tessellate_to_deviation's meshes
// watertight, and only edges that coincide along their whole length are sewn.
#include <gtest/gtest.h>

#include "analysis/mesh/count_boundary_edges.hpp"
#include "analysis/sewing/sew_faces.hpp"
#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "analysis/mesh/weld_exact.hpp"
#include "core/split_curve.hpp"
#include "analysis_shapes.hpp"
#include "samples/capping.hpp"
#include "samples/capping_shapes.hpp"

namespace cadnurbs {
namespace {

void append_meshes(const SceneNode& node, TriangleMesh& all) {
  for (const auto& shape : node.shapes)
    if (const auto* m = std::get_if<TriangleMesh>(&shape.geometry)) append(all, *m);
  for (const auto& child : node.children) append_meshes(child, all);
}

// Boundary and non-manifold edges of the whole scene meshed at D and welded by exact position.
EdgeCounts open_edges(const Scene& scene, double d) {
  TessellationReport report;
  TriangleMesh all;
  append_meshes(tessellate_to_deviation(scene, d, &report).root, all);
  EXPECT_EQ(report.unshared_edge_uses, 0);
  return count_boundary_edges(weld_exact(all));
}

// The unit cube [0,1]^3 as six quads, counter-clockwise seen from outside; the top (z = 1) split in two
// at x = 0.5 when `split_top`.
PolygonMesh cube(bool split_top) {
  PolygonMesh m;
  for (int i = 0; i < 8; ++i) m.positions.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  m.polygons = {{0, 2, 3, 1}, {0, 1, 5, 4}, {1, 3, 7, 5}, {3, 2, 6, 7}, {2, 0, 4, 6}};
  if (!split_top) {
    m.polygons.push_back({4, 5, 7, 6});
    return m;
  }
  m.positions.emplace_back(0.5, 0, 1);  // 8
  m.positions.emplace_back(0.5, 1, 1);  // 9
  m.polygons.push_back({4, 8, 9, 6});
  m.polygons.push_back({8, 5, 7, 9});
  return m;
}

Scene scene_of(Geometry geometry) {
  Scene scene;
  scene.root.shapes.push_back({"part", std::move(geometry), std::nullopt});
  return scene;
}

TEST(SewFaces, PolygonCubeClosesWithTwelveEdges) {
  SewingReport r;
  const Scene sewn = sew_faces(scene_of(cube(false)), {1e-6, 1e-6}, &r);
  EXPECT_EQ(r.faces, 6);
  EXPECT_EQ(r.polygon_faces, 6);
  EXPECT_EQ(r.shared_edges, 12);
  EXPECT_EQ(r.sewn_pieces, 24);
  EXPECT_EQ(r.open_pieces, 0);
  EXPECT_EQ(r.cuts, 0);
  const EdgeCounts e = open_edges(sewn, 0.01);
  EXPECT_EQ(e.boundary, 0);
  EXPECT_EQ(e.non_manifold, 0);
}

TEST(SewFaces, SideAlongTwoNeighboursIsCut) {
  // The front and back tops run along both halves of the split top: each is cut at the half-way vertex.
  SewingReport r;
  const Scene sewn = sew_faces(scene_of(cube(true)), {1e-6, 1e-6}, &r);
  EXPECT_EQ(r.faces, 7);
  EXPECT_EQ(r.cuts, 2);
  EXPECT_EQ(r.shared_edges, 15);  // 12 - 2 halved + 4 halves + the line between the two top quads
  EXPECT_EQ(r.open_pieces, 0);
  const EdgeCounts e = open_edges(sewn, 0.01);
  EXPECT_EQ(e.boundary, 0);
  EXPECT_EQ(e.non_manifold, 0);
}

TEST(SewFaces, FacesPlacedByTransformsAreSewnInWorldCoordinates) {
  // The top quad defined at z = 0 and lifted into place by its node's transform, as a writer's USE does.
  PolygonMesh sides = cube(false);
  sides.polygons.pop_back();
  PolygonMesh top;
  top.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  top.polygons = {{0, 1, 2, 3}};
  Scene scene = scene_of(sides);
  SceneNode lifted;
  lifted.transform = Eigen::Translation3d(0, 0, 1);
  lifted.shapes.push_back({"top", top, std::nullopt});
  scene.root.children.push_back(lifted);
  SewingReport r;
  const Scene sewn = sew_faces(scene, {1e-6, 1e-6}, &r);
  EXPECT_EQ(r.shared_edges, 12);
  EXPECT_TRUE(sewn.root.children[0].transform.matrix().isIdentity(0.0));
  EXPECT_EQ(open_edges(sewn, 0.01).boundary, 0);
}

TEST(SewFaces, TouchingAtAPointOrRunningParallelIsNotSewn) {
  const double d = 0.01;
  const SewingTolerance tolerance{d / 400, d / 4};
  // Two squares meeting at the corner (1,1,0) only.
  PolygonMesh corner;
  corner.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 1, 0}, {2, 2, 0}, {1, 2, 0}};
  corner.polygons = {{0, 1, 2, 3}, {2, 4, 5, 6}};
  SewingReport r;
  sew_faces(scene_of(corner), tolerance, &r);
  EXPECT_EQ(r.shared_edges, 0);
  EXPECT_EQ(r.open_pieces, 8);
  // A square and the same square 10 D above it, facing the other way: parallel edges, never sewn.
  PolygonMesh parallel;
  parallel.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 10 * d}, {1, 0, 10 * d}, {1, 1, 10 * d}, {0, 1, 10 * d}};
  parallel.polygons = {{0, 1, 2, 3}, {4, 7, 6, 5}};
  sew_faces(scene_of(parallel), tolerance, &r);
  EXPECT_EQ(r.shared_edges, 0);
  // The positive control: at the same height the two are sewn along all four sides.
  for (int i = 4; i < 8; ++i) parallel.positions[i].z() = 0;
  sew_faces(scene_of(parallel), tolerance, &r);
  EXPECT_EQ(r.shared_edges, 4);
}

TEST(SewFaces, ModelGapsAreBridgedUpToTheLargestTolerance) {
  // Two unit squares 5e-4 apart along x = 1 (a STEP file's own gap): open at 1e-5, sewn at ten and a
  // hundred times that, only when the largest tolerance allows it.
  PolygonMesh gap;
  gap.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {1.0005, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1.0005, 1, 0}};
  gap.polygons = {{0, 1, 2, 3}, {4, 5, 6, 7}};
  SewingReport r;
  sew_faces(scene_of(gap), {1e-5, 1e-2}, &r);
  EXPECT_EQ(r.shared_edges, 1);
  EXPECT_DOUBLE_EQ(r.widest_gap, 1e-3);
  sew_faces(scene_of(gap), {1e-5, 1e-4}, &r);
  EXPECT_EQ(r.shared_edges, 0);
  EXPECT_EQ(r.widest_gap, 0.0);
}

TEST(SewFaces, SamePairOfVerticesButApartIsTwoEdges) {
  // A disc cut along a diameter into two half discs: both half circles run between the same two
  // vertices and must not be sewn to each other; only the diameter is one edge.
  TrimmedSurface plane;
  NurbsSurface& s = plane.surface;
  s.u_count = s.v_count = 2;
  s.u_knots = s.v_knots = {-1, -1, 1, 1};
  s.points = {{-1, -1, 0}, {1, -1, 0}, {-1, 1, 0}, {1, 1, 0}};
  const auto [upper, lower] = split_curve(test::circle_2d({0, 0}, 0.8), 2.0);  // starts at (0.8, 0)
  TrimmedSurface top = plane, bottom = plane;
  top.loops = {TrimLoop{{upper, Polyline2D{{{-0.8, 0}, {0.8, 0}}}}, {}}};
  bottom.loops = {TrimLoop{{lower, Polyline2D{{{0.8, 0}, {-0.8, 0}}}}, {}}};
  Scene scene;
  scene.root.shapes.push_back({"top", top, std::nullopt});
  scene.root.shapes.push_back({"bottom", bottom, std::nullopt});
  SewingReport r;
  const Scene sewn = sew_faces(scene, {1e-6, 1e-6}, &r);
  EXPECT_EQ(r.shared_edges, 1);
  EXPECT_EQ(r.open_pieces, 2);
  EXPECT_EQ(r.cuts, 0);
  const EdgeCounts e = open_edges(sewn, 0.001);
  EXPECT_GT(e.boundary, 0);  // the rim is open
  EXPECT_EQ(e.non_manifold, 0);
}

TEST(SewFaces, SphereSeamIsSewnAndPolesArePoints) {
  SewingReport r;
  const Scene sewn = sew_faces(scene_of(test::sphere(5.0)), {1e-6, 1e-6}, &r);
  EXPECT_EQ(r.shared_edges, 1);
  EXPECT_EQ(r.sewn_pieces, 2);
  EXPECT_EQ(r.point_pieces, 2);
  EXPECT_EQ(r.open_pieces, 0);
  for (double d : {0.1, 0.01}) {
    const EdgeCounts e = open_edges(sewn, d);
    EXPECT_EQ(e.boundary, 0) << "D=" << d;
    EXPECT_EQ(e.non_manifold, 0) << "D=" << d;
  }
}

TEST(SewFaces, CappingWithoutEdgeIdsSewsLikeTheHandMadeOnes) {
  // samples/capping_edges.cpp names three edges by hand (two lid rims and the body's seam); sewing must
  // find the same three from geometry alone, and close the capping up.
  for (const std::string name : {"capping-90", "capping-end"}) {
    const Scene faces = capping_nurbs(bundled_capping(name));
    EXPECT_GT(open_edges(faces, 0.1).boundary, 0) << name << ": the control, not sewn, has cracks";
    SewingReport r;
    const Scene sewn = sew_faces(faces, {1e-6, 1e-6}, &r);
    EXPECT_EQ(r.shared_edges, 3) << name;
    EXPECT_EQ(r.open_pieces, 0) << name;
    const EdgeCounts e = open_edges(sewn, 0.1);
    EXPECT_EQ(e.boundary, 0) << name;
    EXPECT_EQ(e.non_manifold, 0) << name;
  }
}

TEST(SewFaces, RefusesANonPositiveTolerance) {
  EXPECT_THROW(sew_faces(scene_of(cube(false)), {0.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(sew_faces(scene_of(cube(false)), {1.0, 0.5}), std::invalid_argument);
}

}  // namespace
}  // namespace cadnurbs
