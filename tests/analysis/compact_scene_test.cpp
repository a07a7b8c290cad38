// The exact rewrites of the compact writer, each against what must not change: the point set of trims,
// the surface under a reparametrisation, the area and plane of polygons, the copies of a part.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis_shapes.hpp"
#include "analysis/compaction/compact_scene.hpp"
#include "analysis/compaction/instance_repeated_parts.hpp"
#include "analysis/compaction/join_straight_trim_runs.hpp"
#include "core/knot_removal.hpp"
#include "analysis/compaction/merge_convex_polygons.hpp"
#include "analysis/compaction/planar_face_polygons.hpp"
#include "analysis/measure/trimmed_surface_area.hpp"
#include "analysis/mesh/weld_polygon_meshes.hpp"
#include "analysis/knots/whole_number_knots.hpp"
#include "core/knot_insertion.hpp"
#include "core/knot_vector.hpp"

namespace cadnurbs {
namespace {

NurbsCurve line_2d(Eigen::Vector2d a, Eigen::Vector2d b, double t0 = 0, double t1 = 1) {
  NurbsCurve c;
  c.dimension = 2;
  c.order = 2;
  c.points = {Eigen::Vector3d(a.x(), a.y(), 0), Eigen::Vector3d(b.x(), b.y(), 0)};
  c.knots = {t0, t0, t1, t1};
  return c;
}

// The plane z = 0 over [0, width] x [0, height] as a bilinear patch with (u,v) = (x,y).
NurbsSurface plane(double width, double height) {
  NurbsSurface s;
  s.u_count = s.v_count = 2;
  s.u_knots = {0, 0, width, width};
  s.v_knots = {0, 0, height, height};
  s.points = {{0, 0, 0}, {width, 0, 0}, {0, height, 0}, {width, height, 0}};
  return s;
}

TrimLoop square_loop(double x0, double y0, double x1, double y1, bool clockwise = false) {
  std::vector<Eigen::Vector2d> c = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  if (clockwise) std::reverse(c.begin(), c.end());
  TrimLoop loop;
  for (size_t i = 0; i < 4; ++i) loop.segments.emplace_back(line_2d(c[i], c[(i + 1) % 4]));
  return loop;
}

double polygon_mesh_area(const PolygonMesh& mesh) { return mesh_area(triangulated(mesh)); }

bool convex_polygons(const PolygonMesh& mesh, const Eigen::Vector3d& normal) {
  for (const auto& polygon : mesh.polygons)
    for (size_t i = 0; i < polygon.size(); ++i) {
      const auto& a = mesh.positions[polygon[i]];
      const auto& b = mesh.positions[polygon[(i + 1) % polygon.size()]];
      const auto& c = mesh.positions[polygon[(i + 2) % polygon.size()]];
      if ((b - a).cross(c - b).dot(normal) < -1e-12) return false;
    }
  return true;
}

TEST(JoinStraightTrimRuns, StraightSegmentsBecomeOnePolylineWithoutCollinearPoints) {
  TrimLoop loop;
  // A unit square whose bottom edge is split in two, then a quarter circle replacing the top-left corner.
  loop.segments.emplace_back(line_2d({0, 0}, {0.5, 0}, 3, 7));
  loop.segments.emplace_back(line_2d({0.5, 0}, {1, 0}));
  loop.segments.emplace_back(line_2d({1, 0}, {1, 1}));
  loop.segments.emplace_back(line_2d({1, 1}, {0.2, 1}));
  NurbsCurve arc = test::circle_2d({0.2, 0.8}, 0.2);  // its second quarter runs from (0.2,1) to (0,0.8)
  NurbsCurve quarter;
  quarter.dimension = 2;
  quarter.order = 3;
  quarter.points = {arc.points[2], arc.points[3], arc.points[4]};
  quarter.weights = {arc.weights[2], arc.weights[3], arc.weights[4]};
  quarter.knots = {0, 0, 0, 1, 1, 1};
  loop.segments.emplace_back(quarter);
  loop.segments.emplace_back(line_2d({0, 0.8}, {0, 0}));
  loop.edges.assign(loop.segments.size(), TrimEdgeRef{7, false});
  int runs = 0;
  const TrimLoop out = join_straight_trim_runs(loop, 1e-9, &runs);
  // Starts at the arc; the run (0,0.8) -> (0,0) -> (0.5,0) -> (1,0) -> (1,1) -> (0.2,1) is one polyline
  // without the collinear (0.5, 0).
  ASSERT_EQ(out.segments.size(), 2u);
  EXPECT_TRUE(std::holds_alternative<NurbsCurve>(out.segments[0]));
  const auto& polyline = std::get<Polyline2D>(out.segments[1]);
  ASSERT_EQ(polyline.points.size(), 5u);
  EXPECT_EQ(polyline.points[0], Eigen::Vector2d(0, 0.8));
  EXPECT_EQ(polyline.points[1], Eigen::Vector2d(0, 0));
  EXPECT_EQ(polyline.points[2], Eigen::Vector2d(1, 0));
  EXPECT_EQ(polyline.points[4], Eigen::Vector2d(0.2, 1));
  EXPECT_EQ(runs, 1);
  EXPECT_EQ(out.edges[0].edge, 7);   // the arc keeps its edge
  EXPECT_EQ(out.edges[1].edge, -1);  // a joined run is no single edge
  EXPECT_LT(loop_closure_gap(out), 1e-12);
}

TEST(JoinStraightTrimRuns, CurvesAreStraightOnlyWithinTheTolerance) {
  NurbsCurve cubic;
  cubic.dimension = 2;
  cubic.order = 4;
  cubic.knots = {0, 0, 0, 0, 1, 1, 1, 1};
  cubic.points = {{0, 0, 0}, {0.3, 1e-7, 0}, {0.6, -1e-7, 0}, {1, 0, 0}};
  const auto straight = straight_segment_points(cubic, 2e-7);
  ASSERT_TRUE(straight);
  EXPECT_EQ(straight->size(), 2u);
  EXPECT_FALSE(straight_segment_points(cubic, 0.5e-7));
  cubic.points = {{0, 0, 0}, {1.2, 0, 0}, {0.6, 0, 0}, {1, 0, 0}};  // on the line, but runs past its end
  EXPECT_FALSE(straight_segment_points(cubic, 1e-6));
}

TEST(WholeNumberKnots, ThirdsOfATurnBecomeIntegersAndTheSurfaceStaysPut) {
  const double third = 2.0 * M_PI / 3.0;
  const auto map = whole_number_knot_map({0, 0, 0, third, third, 2 * third, 2 * third, 3 * third, 3 * third, 3 * third});
  ASSERT_TRUE(map);
  EXPECT_EQ(mapped_knots({0, 0, 0, third, third, 2 * third, 2 * third, 3 * third, 3 * third, 3 * third}, *map),
            (std::vector<double>{0, 0, 0, 1, 1, 2, 2, 3, 3, 3}));
  EXPECT_FALSE(whole_number_knot_map({0, 0, 1, 2, 2}));          // already whole
  EXPECT_FALSE(whole_number_knot_map({0, 0, 0.3, 0.71, 1, 1}));  // no small unit fits
  const auto tenths = whole_number_knot_map({0, 0, 0.3, 0.7, 1, 1});
  ASSERT_TRUE(tenths);
  EXPECT_EQ(mapped_knots({0, 0, 0.3, 0.7, 1, 1}, *tenths), (std::vector<double>{0, 0, 3, 7, 10, 10}));
  const auto spans = whole_number_knot_map({5, 5, 5.5, 6.25, 6.25});  // spans 0.5 and 0.75: unit 0.25
  ASSERT_TRUE(spans);
  EXPECT_EQ(mapped_knots({5, 5, 5.5, 6.25, 6.25}, *spans), (std::vector<double>{0, 0, 2, 5, 5}));

  // A plane in odd parameter units with trims at odd places: mapped (shorter), and every trim point
  // lands on the same 3D point.
  TrimmedSurface face;
  face.surface = plane(10.337675, 4.18879);
  face.surface.u_knots = {-3.1234567, -3.1234567, 7.2142183, 7.2142183};
  face.loops.push_back(square_loop(-3.1234567 + 10.337675 / 3, 4.18879 / 3, 7.2142183, 4.18879));
  std::vector<Eigen::Vector3d> before;
  for (const auto& segment : face.loops[0].segments) {
    const auto start = segment_start(segment);
    before.push_back(surface_point(face.surface, start.x(), start.y()));
  }
  const size_t long_form = written_length(face, 1e-6);
  EXPECT_EQ(use_whole_number_knots(face, 1e-6), 2);  // u and v; the trimming lines' knots are whole already
  EXPECT_LT(written_length(face, 1e-6), long_form);
  EXPECT_EQ(face.surface.u_knots, (std::vector<double>{0, 0, 1, 1}));
  EXPECT_EQ(face.surface.v_knots, (std::vector<double>{0, 0, 1, 1}));
  for (size_t i = 0; i < before.size(); ++i) {
    const auto start = segment_start(face.loops[0].segments[i]);
    EXPECT_LT((surface_point(face.surface, start.x(), start.y()) - before[i]).norm(), 1e-12);
  }
  // A plane in millimetres with trims at round millimetres stays as it is: [0, 1] would make them long.
  TrimmedSurface round;
  round.surface = plane(127, 63.5);
  round.surface.u_knots = {-63.5, -63.5, 63.5, 63.5};
  round.loops.push_back(square_loop(-60, 2.25, 38.1, 50.8));
  EXPECT_EQ(use_whole_number_knots(round, 1e-6), 0);
  EXPECT_EQ(round.surface.u_knots, (std::vector<double>{-63.5, -63.5, 63.5, 63.5}));
}

TEST(KnotRemoval, InsertedKnotsComeOutAgainAndTheCurveStaysWithinTheTolerance) {
  NurbsCurve c;
  c.dimension = 2;
  c.order = 4;
  c.knots = {0, 0, 0, 0, 0.5, 1, 1, 1, 1};
  c.points = {{0, 0, 0}, {1, 2, 0}, {2, -1, 0}, {3, 1, 0}, {4, 0, 0}};
  const NurbsCurve refined = refine_knots(c, {0.1, 0.2, 0.25, 0.7, 0.75, 0.9});
  int removed = 0;
  const NurbsCurve back = remove_knots(refined, 1e-9, &removed);
  EXPECT_EQ(removed, 6);
  EXPECT_EQ(back.count(), c.count());
  for (int k = 0; k <= 100; ++k) EXPECT_LT((curve_point(back, k / 100.0) - curve_point(c, k / 100.0)).norm(), 1e-9);

  // A wiggly curve keeps its knots at a tight tolerance and loses some at a loose one, staying within it.
  NurbsCurve wiggly;
  wiggly.dimension = 2;
  wiggly.order = 4;
  wiggly.knots = clamped_uniform_knots(4, 30);
  for (int i = 0; i < 30; ++i) wiggly.points.emplace_back(i, 0.3 * std::sin(1.7 * i) + 0.01 * std::cos(5.0 * i), 0);
  EXPECT_EQ(remove_knots(wiggly, 1e-12, &removed).count(), 30);
  EXPECT_EQ(removed, 0);
  const NurbsCurve loose = remove_knots(wiggly, 0.05, &removed);
  EXPECT_GT(removed, 0);
  EXPECT_EQ(loose.count(), 30 - removed);
  for (int k = 0; k <= 2000; ++k)
    EXPECT_LE((curve_point(loose, k / 2000.0) - curve_point(wiggly, k / 2000.0)).norm(), 0.05);
}

TEST(PlanarFacePolygons, SquareWithAHoleIsConvexPiecesOfTheRightArea) {
  TrimmedSurface face{plane(4, 4), {}};
  face.loops.push_back(square_loop(0, 0, 4, 4));
  face.loops.push_back(square_loop(1, 1, 2, 3, /*clockwise=*/true));
  const auto mesh = planar_face_polygons(face, 1e-9);
  ASSERT_TRUE(mesh);
  EXPECT_NEAR(polygon_mesh_area(*mesh), 16.0 - 2.0, 1e-12);
  EXPECT_TRUE(convex_polygons(*mesh, Eigen::Vector3d::UnitZ()));
  for (const auto& p : mesh->positions) EXPECT_EQ(p.z(), 0.0);
  // 8 corners and a hole: 8 triangles; convex pieces need fewer.
  EXPECT_LT(mesh->polygons.size(), 8u);
  EXPECT_GE(mesh->polygons.size(), 4u);
}

TEST(PlanarFacePolygons, ConvexLoopIsOnePolygonAndATrapezoidPatchQualifies) {
  TrimmedSurface face{plane(4, 4), {}};
  face.loops.push_back(square_loop(1, 1, 3, 2));
  auto mesh = planar_face_polygons(face, 1e-9);
  ASSERT_TRUE(mesh);
  ASSERT_EQ(mesh->polygons.size(), 1u);
  EXPECT_EQ(mesh->polygons[0].size(), 4u);
  EXPECT_NEAR(polygon_mesh_area(*mesh), 2.0, 1e-12);

  // A planar trapezoid (not a parallelogram): untrimmed it is its four corners.
  TrimmedSurface trapezoid{plane(1, 1), {}};
  trapezoid.surface.points = {{0, 0, 0}, {4, 0, 0}, {1, 2, 0}, {3, 2, 0}};
  mesh = planar_face_polygons(trapezoid, 1e-9);
  ASSERT_TRUE(mesh);
  EXPECT_NEAR(polygon_mesh_area(*mesh), 0.5 * (4 + 2) * 2, 1e-12);
  // ... but a diagonal trim on it would bend in 3D: refused.
  trapezoid.loops.push_back(TrimLoop{});
  for (auto [a, b] : std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>>{{{0, 0}, {1, 0}}, {{1, 0}, {0, 1}}, {{0, 1}, {0, 0}}})
    trapezoid.loops[0].segments.emplace_back(line_2d(a, b));
  EXPECT_FALSE(planar_face_polygons(trapezoid, 1e-9));

  // A twisted patch is not planar; a curved trim is not straight.
  TrimmedSurface twisted{plane(1, 1), {}};
  twisted.surface.points[3].z() = 0.01;
  EXPECT_FALSE(planar_face_polygons(twisted, 1e-9));
  EXPECT_FALSE(planar_face_polygons(test::trimmed_square(2, 0.4, 0.1), 1e-9));
}

TEST(MergeConvexPolygons, FanOfAConvexPolygonIsOnePolygon) {
  std::vector<Eigen::Vector2d> points;
  for (int k = 0; k < 8; ++k) points.emplace_back(std::cos(k * M_PI / 4), std::sin(k * M_PI / 4));
  std::vector<std::array<int, 3>> fan;
  for (int k = 1; k + 1 < 8; ++k) fan.push_back({0, k, k + 1});
  const auto polygons = merge_convex_polygons(points, fan, 1e-12);
  ASSERT_EQ(polygons.size(), 1u);
  EXPECT_EQ(polygons[0].size(), 8u);
  // An L shape cannot be one convex polygon.
  const std::vector<Eigen::Vector2d> l = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  const std::vector<std::array<int, 3>> triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}};
  EXPECT_EQ(merge_convex_polygons(l, triangles, 1e-12).size(), 2u);
}

TEST(WeldPolygonMeshes, CornersThatDifferInTheLastBitsBecomeOne) {
  PolygonMesh a{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2, 3}}};
  PolygonMesh b{{{1 + 1e-13, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1 - 1e-13, 0}}, {{0, 1, 2, 3}}};
  const PolygonMesh welded = weld_polygon_meshes({a, b}, 1e-9);
  EXPECT_EQ(welded.positions.size(), 6u);
  ASSERT_EQ(welded.polygons.size(), 2u);
  EXPECT_EQ(welded.polygons[1][0], 1);
  EXPECT_EQ(welded.polygons[1][3], 2);
}

// Two faces of a "pin" sharing edge `first`: a bilinear plane and a quarter cylinder.
std::vector<Shape> pin(int first, const Eigen::Affine3d& place, bool reverse_u) {
  TrimmedSurface side = test::quarter_cylinder(1, 3);
  TrimmedSurface top{plane(2, 1), {}};
  top.loops.push_back(square_loop(0, 0, 2, 1));
  top.loops[0].edges = {{first, false}, {-1, false}, {-1, false}, {-1, false}};
  side.loops.push_back(square_loop(side.surface.u_start(), side.surface.v_start(), side.surface.u_end(), side.surface.v_end()));
  side.loops[0].edges = {{first, true}, {-1, false}, {-1, false}, {-1, false}};
  for (auto* face : {&side, &top}) {
    for (auto& p : face->surface.points) p = place * p;
    if (reverse_u) {  // the same surface with u running the other way
      NurbsSurface& s = face->surface;
      NurbsSurface r = s;
      for (int j = 0; j < s.v_count; ++j)
        for (int i = 0; i < s.u_count; ++i) {
          r.points[r.index(i, j)] = s.point(s.u_count - 1 - i, j);
          if (s.is_rational()) r.weights[r.index(i, j)] = s.weight(s.u_count - 1 - i, j);
        }
      for (size_t k = 0; k < s.u_knots.size(); ++k) r.u_knots[k] = s.u_knots.front() + s.u_knots.back() - s.u_knots[s.u_knots.size() - 1 - k];
      const double u0 = s.u_knots.front(), u1 = s.u_knots.back();
      for (auto& loop : face->loops)
        for (auto& segment : loop.segments)
          for (auto& p : std::get<NurbsCurve>(segment).points) p.x() = u0 + u1 - p.x();
      s = r;
    }
  }
  return {Shape{"", TrimmedSurface(side), Colour{1, 0, 0}}, Shape{"", TrimmedSurface(top), Colour{1, 0, 0}}};
}

TEST(InstanceRepeatedParts, CopiesUnderAMotionAreFoundWhateverTheirParametrisation) {
  SceneNode node;
  Eigen::Affine3d moved = Eigen::Affine3d::Identity();
  moved.translate(Eigen::Vector3d(5, -2, 1)).rotate(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  for (auto& s : pin(0, Eigen::Affine3d::Identity(), false)) node.shapes.push_back(s);
  for (auto& s : pin(1, moved, true)) node.shapes.push_back(s);
  Eigen::Affine3d shifted = Eigen::Affine3d::Identity();
  shifted.translate(Eigen::Vector3d(0, 0, 10));
  for (auto& s : pin(2, shifted, false)) node.shapes.push_back(s);
  // A different part: the pin stretched.
  Eigen::Affine3d stretched = Eigen::Affine3d::Identity();
  stretched.scale(Eigen::Vector3d(1, 1, 1.5));
  for (auto& s : pin(3, stretched, false)) node.shapes.push_back(s);

  EXPECT_EQ(instance_repeated_parts(node, 1e-9), 2);
  ASSERT_EQ(node.children.size(), 3u);
  EXPECT_EQ(node.shapes.size(), 2u);  // the stretched pin stays
  EXPECT_TRUE(node.children[0].transform.matrix().isIdentity(0));
  EXPECT_TRUE(node.children[1].transform.isApprox(moved, 1e-12));
  EXPECT_TRUE(node.children[2].transform.isApprox(shifted, 1e-12));
  // Copies hold the original's shapes: the placed copy covers the moved pin's surface.
  const auto& copy = std::get<TrimmedSurface>(node.children[1].shapes[0].geometry);
  const TrimmedSurface original_side = std::get<TrimmedSurface>(pin(1, moved, true)[0].geometry);
  const Eigen::Vector3d p = node.children[1].transform * surface_point(copy.surface, copy.surface.u_start(), 0.5);
  EXPECT_LT((p - surface_point(original_side.surface, original_side.surface.u_end(), 0.5)).norm(), 1e-12);
}

// The entry times 10^digits is a whole number, as a writer's exact decimals read it back.
bool decimal_with(double value, int digits) {
  const double scale = std::pow(10.0, digits);
  return std::round(value * scale) / scale == value;
}

TEST(InstanceRepeatedParts, MotionsAreRoundedToTheFewestDecimalsThatStillLandTheCopy) {
  SceneNode node;
  // A quarter turn and a pitch of 3.81: least squares finds 4.4e-16 for 0 and 3.8100000000000005 for 3.81.
  Eigen::Affine3d quarter = Eigen::Affine3d::Identity();
  quarter.translate(Eigen::Vector3d(3.81, 0, 0)).rotate(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  // A turn of 0.3 radians: no short decimals land it within 1e-9.
  Eigen::Affine3d turned = Eigen::Affine3d::Identity();
  turned.translate(Eigen::Vector3d(0, 7.62, 0)).rotate(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()));
  for (auto& s : pin(0, Eigen::Affine3d::Identity(), false)) node.shapes.push_back(s);
  for (auto& s : pin(1, quarter, false)) node.shapes.push_back(s);
  for (auto& s : pin(2, turned, false)) node.shapes.push_back(s);

  ASSERT_EQ(instance_repeated_parts(node, 1e-9), 2);
  ASSERT_EQ(node.children.size(), 3u);
  const Eigen::Affine3d& q = node.children[1].transform;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_EQ(q.linear()(i, j), std::round(quarter.linear()(i, j))) << i << " " << j;
  EXPECT_EQ(q.translation(), Eigen::Vector3d(3.81, 0, 0));
  const Eigen::Affine3d& t = node.children[2].transform;
  bool short_decimals = true;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) short_decimals = short_decimals && decimal_with(t.matrix()(i, j), 12);
  EXPECT_TRUE(short_decimals);
  EXPECT_FALSE(decimal_with(t.linear()(1, 1), 8));  // cos 0.3 needs more digits than that
  // Each copy still lands on the part it replaces within the tolerance.
  for (auto [child, motion, index] : {std::tuple{1, quarter, 1}, std::tuple{2, turned, 2}}) {
    const auto& copy = std::get<TrimmedSurface>(node.children[child].shapes[0].geometry).surface;
    const std::vector<Shape> moved_pin = pin(index, motion, false);
    const auto& original = std::get<TrimmedSurface>(moved_pin[0].geometry).surface;
    for (size_t k = 0; k < copy.points.size(); ++k)
      EXPECT_LT((node.children[child].transform * copy.points[k] - original.points[k]).norm(), 1e-9) << child << " " << k;
  }
}

TEST(CompactScene, TheCappingKeepsItsAreaAndItsLidsBecomePolygons) {
  Scene scene;
  scene.root.shapes.push_back({"", test::trimmed_square(2, 0.4, 0.1), std::nullopt});
  TrimmedSurface lid{plane(3, 2), {}};
  lid.loops.push_back(square_loop(0.5, 0.5, 2.5, 1.5));
  scene.root.shapes.push_back({"", lid, std::nullopt});
  const double before = trimmed_surface_area(std::get<TrimmedSurface>(scene.root.shapes[0].geometry), 1e-10) + 2.0;
  CompactReport report;
  const Scene out = compact_scene(scene, 1e-6, &report);
  EXPECT_EQ(report.planar_faces, 1);
  EXPECT_EQ(report.polygon_meshes, 1);
  ASSERT_EQ(out.root.shapes.size(), 2u);
  const auto& polygons = std::get<PolygonMesh>(out.root.shapes[0].geometry);
  const auto& annulus = std::get<TrimmedSurface>(out.root.shapes[1].geometry);
  EXPECT_NEAR(trimmed_surface_area(annulus, 1e-10) + polygon_mesh_area(polygons), before, 1e-8);
  EXPECT_THROW(compact_scene(scene, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace cadnurbs
