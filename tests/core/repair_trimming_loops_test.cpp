// repair_trimming_loops: the faults of real files (a loop bounding no area, a loop a little outside the
// domain, a loop crossing itself) repaired or refused, with the exact messages.
#include <gtest/gtest.h>

#include "core/geometry_error.hpp"
#include "core/nurbs_surface.hpp"
#include "core/polygon_2d.hpp"
#include "core/repair_trimming_loops.hpp"

using namespace cadnurbs;

namespace {

TrimLoop polyline_loop(std::vector<Eigen::Vector2d> points) {
  points.push_back(points.front());
  TrimLoop loop;
  loop.segments.emplace_back(Polyline2D{std::move(points)});
  return loop;
}

// A dome over [0, 1]^2: biquadratic, so not widened like a bilinear patch.
TrimmedSurface dome() {
  TrimmedSurface t;
  NurbsSurface& s = t.surface;
  s.u_order = s.v_order = 3;
  s.u_count = s.v_count = 3;
  s.u_knots = s.v_knots = {0, 0, 0, 1, 1, 1};
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) s.points.emplace_back(0.5 * i, 0.5 * j, (i == 1 && j == 1) ? 1.0 : 0.0);
  return t;
}

TrimmedSurface plane() {
  TrimmedSurface t;
  t.surface.u_count = t.surface.v_count = 2;
  t.surface.u_knots = t.surface.v_knots = {0, 0, 1, 1};
  t.surface.points = {{0, 0, 0}, {2, 0, 0}, {0, 1, 1}, {2, 1, 1}};
  return t;
}

double worst_outside(const TrimmedSurface& t) {
  double worst = 0;
  for (const auto& loop : t.loops)
    for (const auto& p : loop_polygon(loop))
      worst = std::max({worst, t.surface.u_start() - p.x(), p.x() - t.surface.u_end(), t.surface.v_start() - p.y(),
                        p.y() - t.surface.v_end()});
  return worst;
}

std::string refusal(TrimmedSurface t) {
  try {
    repair_trimming_loops(t, "face 7");
  } catch (const GeometryError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(RepairTrimmingLoops, ValidLoopsAreLeftAlone) {
  TrimmedSurface t = dome();
  t.loops.push_back(polyline_loop({{0.1, 0.1}, {0.9, 0.1}, {0.9, 0.9}, {0.1, 0.9}}));
  const TrimmedSurface before = t;
  EXPECT_TRUE(repair_trimming_loops(t, "face 7").empty());
  EXPECT_EQ(std::get<Polyline2D>(t.loops[0].segments[0]).points,
            std::get<Polyline2D>(before.loops[0].segments[0]).points);
}

TEST(RepairTrimmingLoops, ALoopThatBoundsNoAreaIsDropped) {
  TrimmedSurface t = dome();
  t.loops.push_back(polyline_loop({{0.1, 0.1}, {0.9, 0.1}, {0.9, 0.9}, {0.1, 0.9}}));
  t.loops.push_back(polyline_loop({{0.3, 0.3}, {0.6, 0.3}}));  // there and back: no area
  const auto done = repair_trimming_loops(t, "face 7");
  ASSERT_EQ(done.size(), 1u);
  EXPECT_EQ(done[0], "trimming loop 1 bounds no area: dropped");
  ASSERT_EQ(t.loops.size(), 1u);
  EXPECT_NEAR(loop_signed_area(t.loops[0]), 0.64, 1e-12);
}

TEST(RepairTrimmingLoops, AFaceWhoseLoopsAllBoundNoAreaIsRefused) {
  TrimmedSurface t = dome();
  t.loops.push_back(polyline_loop({{0.3, 0.3}, {0.6, 0.3}, {0.9, 0.3}}));
  EXPECT_EQ(refusal(t), "face 7: every trimming loop bounds no area: the face has no area");
}

// In a scene, such a face is taken out with a line (one bad face never costs the file): our own .cnb of
// a Bourns toroid, whose quantised trims of a 1e-6 mm^2 face collapse, failed whole on reading back.
TEST(RepairTrimmingLoops, ASceneDropsAFaceWithoutArea) {
  TrimmedSurface flat = dome();
  flat.loops.push_back(polyline_loop({{0.2, 0.2}, {0.8, 0.2}, {0.5, 0.2}}));
  TrimmedSurface good = dome();
  good.loops.push_back(polyline_loop({{0.2, 0.2}, {0.8, 0.2}, {0.5, 0.8}}));
  Scene scene;
  scene.root.name = "part";
  scene.root.shapes.push_back({"flat", flat, std::nullopt});
  scene.root.shapes.push_back({"good", good, std::nullopt});
  const auto done = repair_trimming_loops(scene);
  ASSERT_EQ(done.size(), 1u);
  EXPECT_EQ(done[0], "part/flat: every trimming loop bounds no area: the face has no area: dropped");
  ASSERT_EQ(scene.root.shapes.size(), 1u);
  EXPECT_EQ(scene.root.shapes[0].name, "good");
}

TEST(RepairTrimmingLoops, RoundOffOutsideTheDomainIsClampedWithoutAWord) {
  TrimmedSurface t = dome();
  t.loops.push_back(polyline_loop({{0.0, 0.0}, {1.0 + 5e-13, 0.0}, {1.0, 1.0}, {0.0, 1.0}}));
  EXPECT_TRUE(repair_trimming_loops(t, "face 7").empty());
  EXPECT_LE(worst_outside(t), 0.0);
}

TEST(RepairTrimmingLoops, ALoopALittleOutsideIsMovedOntoTheDomainAndReported) {
  TrimmedSurface t = dome();
  t.loops.push_back(polyline_loop({{0.2, -1e-4}, {0.8, -1e-4}, {0.8, 0.5}, {0.2, 0.5}}));
  const auto done = repair_trimming_loops(t, "face 7");
  ASSERT_EQ(done.size(), 1u);
  EXPECT_EQ(done[0], "trimming loop 0 left the surface's domain by 0.0001 of its size: 3 points moved onto the "
                     "domain's edge");  // the closing point counts too
  EXPECT_LE(worst_outside(t), 0.0);
  EXPECT_NEAR(loop_signed_area(t.loops[0]), 0.6 * 0.5, 1e-12);
}

TEST(RepairTrimmingLoops, AnArcWhoseControlPolygonLeavesButNotTheArcIsLeftAlone) {
  TrimmedSurface t = dome();
  NurbsCurve arc;
  arc.dimension = 2;
  arc.order = 3;
  arc.knots = {0, 0, 0, 1, 1, 1};
  arc.points = {{0.1, 0.5, 0}, {0.5, 1.3, 0}, {0.9, 0.5, 0}};  // peaks at v = 0.9
  TrimLoop loop;
  loop.segments.emplace_back(arc);
  loop.segments.emplace_back(Polyline2D{{{0.9, 0.5}, {0.1, 0.5}}});
  t.loops.push_back(loop);
  EXPECT_TRUE(repair_trimming_loops(t, "face 7").empty());
  EXPECT_EQ(std::get<NurbsCurve>(t.loops[0].segments[0]).points[1].y(), 1.3);
}

TEST(RepairTrimmingLoops, ALoopFarOutsideIsRefused) {
  TrimmedSurface t = dome();
  t.loops.push_back(polyline_loop({{0.2, -0.1}, {0.8, -0.1}, {0.8, 0.5}, {0.2, 0.5}}));
  EXPECT_EQ(refusal(t), "face 7: trimming loop 0 leaves the surface's domain by 0.1 of its size (more than 0.01 "
                        "cannot be moved onto it)");
}

// Under GLU's rule (VRML/X3D) the same loop is cut to the domain: the rectangle [0.2, 0.8] x [0, 0.5].
TEST(RepairTrimmingLoops, UnderGlusRuleALoopFarOutsideIsCutToTheDomain) {
  TrimmedSurface t = dome();
  t.loops.push_back(polyline_loop({{0.2, -0.1}, {0.8, -0.1}, {0.8, 0.5}, {0.2, 0.5}}));
  const auto done = repair_trimming_loops(t, "face 7", LoopsOutsideDomain::cut);
  ASSERT_EQ(done.size(), 1u);
  EXPECT_EQ(done[0], "trimming loop 0 leaves the surface's domain by 0.1 of its size: cut to the domain, as GLU-based "
                     "viewers draw it (1 loop left)");
  ASSERT_EQ(t.loops.size(), 1u);
  EXPECT_NEAR(polygon_signed_area(loop_polygon(t.loops[0])), 0.3, 1e-15);
  EXPECT_LE(worst_outside(t), 0.0);
  // Nothing of a loop beside the domain is drawn: the face has no area.
  TrimmedSurface beside = dome();
  beside.loops.push_back(polyline_loop({{2, 0}, {3, 0}, {3, 1}}));
  try {
    repair_trimming_loops(beside, "face 7", LoopsOutsideDomain::cut);
    ADD_FAILURE() << "no refusal";
  } catch (const GeometryError& e) {
    EXPECT_STREQ(e.what(), "face 7: no trimming loop meets the surface's domain: the face has no area");
  }
}

// A surface that joins itself in u (first and last columns of control points equal): a loop one domain
// width to the right is the same loop, moved back; on the dome, which does not join itself, it is refused.
TEST(RepairTrimmingLoops, ALoopAPeriodAwayOnASurfaceThatJoinsItselfIsMovedBack) {
  TrimmedSurface t;
  NurbsSurface& s = t.surface;
  s.u_order = 2, s.v_order = 2, s.u_count = 4, s.v_count = 2;
  s.u_knots = {0, 0, 1, 2, 3, 3};
  s.v_knots = {0, 0, 1, 1};
  for (int j = 0; j < 2; ++j)
    for (const Eigen::Vector3d& p : {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(1, 0, 0)})
      s.points.push_back(p + Eigen::Vector3d(0, 0, j));
  t.loops.push_back(polyline_loop({{3.5, 0.2}, {4.5, 0.2}, {4.5, 0.8}, {3.5, 0.8}}));
  const auto done = repair_trimming_loops(t, "face 7");
  ASSERT_EQ(done.size(), 1u);
  EXPECT_EQ(done[0], "trimming loop 0 lay whole periods off the domain (1 in u) on a surface that joins itself there: moved back");
  EXPECT_EQ(std::get<Polyline2D>(t.loops[0].segments[0]).points[0], Eigen::Vector2d(0.5, 0.2));
  TrimmedSurface open = dome();
  open.loops.push_back(polyline_loop({{1.2, 0.2}, {1.8, 0.2}, {1.8, 0.8}, {1.2, 0.8}}));
  EXPECT_EQ(refusal(open), "face 7: trimming loop 0 leaves the surface's domain by 0.8 of its size (more than 0.01 cannot be "
                           "moved onto it)");
}

TEST(RepairTrimmingLoops, ABilinearPatchIsWidenedExactly) {
  TrimmedSurface t = plane();
  t.loops.push_back(polyline_loop({{-0.5, 0.2}, {0.8, 0.2}, {0.8, 1.5}, {-0.5, 1.5}}));
  const auto done = repair_trimming_loops(t, "face 7");
  ASSERT_EQ(done.size(), 1u);
  EXPECT_EQ(done[0], "trimming loops left the bilinear patch's domain by 0.5 of its size: domain widened (the patch "
                     "extends exactly)");
  EXPECT_EQ(t.surface.u_start(), -0.5);
  EXPECT_EQ(t.surface.v_end(), 1.5);
  EXPECT_LE(worst_outside(t), 0.0);
  // The same plane: (u, v) -> (2u, v, v) before and after.
  for (const Eigen::Vector2d& uv : {Eigen::Vector2d(-0.5, 0.2), Eigen::Vector2d(0.3, 1.5), Eigen::Vector2d(0.8, 0.7)})
    EXPECT_LT((surface_point(t.surface, uv.x(), uv.y()) - Eigen::Vector3d(2 * uv.x(), uv.y(), uv.y())).norm(), 1e-14);
}

TEST(RepairTrimmingLoops, ALoopCrossingItselfIsRefused) {
  TrimmedSurface t = dome();
  // A figure of eight: (0.2,0.2) -> (0.8,0.8) crosses (0.8,0.2) -> (0.2,0.8).
  t.loops.push_back(polyline_loop({{0.2, 0.2}, {0.8, 0.8}, {0.8, 0.3}, {0.2, 0.8}}));
  EXPECT_EQ(refusal(t),
            "face 7: trimming loop 0 crosses itself (its smaller lobe bounds 0.694 of the larger's area; lobes up to "
            "0.1 are cut off)");
}

TEST(RepairTrimmingLoops, ASmallCurlOfAPolylineIsCutOff) {
  TrimmedSurface t = dome();
  // A square whose bottom side curls round a 0.02 square at (0.5, 0.2) and goes on 0.02 lower.
  t.loops.push_back(polyline_loop({{0.2, 0.2},
                                   {0.52, 0.2},
                                   {0.52, 0.22},
                                   {0.5, 0.22},
                                   {0.5, 0.18},
                                   {0.8, 0.18},
                                   {0.8, 0.8},
                                   {0.2, 0.8}}));
  const auto done = repair_trimming_loops(t, "face 7");
  ASSERT_EQ(done.size(), 1u);
  EXPECT_EQ(done[0], "trimming loop 0 crossed itself at (0.5, 0.2): a lobe of 0.00109 of its area cut off");
  // 0.6 x 0.6 and the 0.3 x 0.02 strip below, the 0.02 x 0.02 curl gone.
  EXPECT_NEAR(loop_signed_area(t.loops[0]), 0.366, 1e-14);
  EXPECT_TRUE(repair_trimming_loops(t, "face 7").empty());
}

TEST(RepairTrimmingLoops, TheLoopOfANodalCubicIsCutOffAtItsNode) {
  // x = t^2 - 1, y = t (t^2 - 1) over t in [-1.3, 1.3] as one cubic Bezier, scaled by 0.01: it passes
  // its node (0, 0) at t = -1 and t = 1, and the loop between bounds 8/15 (times 1e-4) counter-clockwise,
  // while the rest of the loop runs clockwise.
  const double a = -1.3, b = 1.3, scale = 0.01;
  auto c = [&](double t) { return Eigen::Vector3d(scale * (t * t - 1), scale * t * (t * t - 1), 0); };
  auto dc = [&](double t) { return Eigen::Vector3d(scale * 2 * t, scale * (3 * t * t - 1), 0); };
  NurbsCurve cubic;
  cubic.dimension = 2;
  cubic.order = 4;
  cubic.knots = {a, a, a, a, b, b, b, b};
  cubic.points = {c(a), c(a) + (b - a) / 3 * dc(a), c(b) - (b - a) / 3 * dc(b), c(b)};
  TrimmedSurface t = dome();
  const Eigen::Vector2d shift(0.3, 0.5);
  for (auto& p : cubic.points) p.head<2>() += shift;
  TrimLoop loop;
  loop.segments.emplace_back(cubic);
  // Closed by a rectangle to the right, 0.6 long.
  const Eigen::Vector2d end = c(b).head<2>() + shift, start = c(a).head<2>() + shift;
  loop.segments.emplace_back(Polyline2D{{end, {0.9, end.y()}, {0.9, start.y()}, start}});
  loop.edges = {{3, false}, {4, true}};
  t.loops.push_back(loop);
  auto area = [](const TrimLoop& l) { return polygon_signed_area(loop_polygon(l, 4096)); };
  const double before = area(t.loops[0]);
  const auto done = repair_trimming_loops(t, "face 7");
  ASSERT_EQ(done.size(), 1u);
  EXPECT_EQ(done[0].rfind("trimming loop 0 crossed itself at (0.3, 0.5): a lobe of ", 0), 0u) << done[0];
  const TrimLoop& cut = t.loops[0];
  // The cubic's two outer pieces, split at t = -1 and t = 1, and the rectangle.
  ASSERT_EQ(cut.segments.size(), 3u);
  const auto& first = std::get<NurbsCurve>(cut.segments[0]);
  const auto& second = std::get<NurbsCurve>(cut.segments[1]);
  EXPECT_NEAR(first.domain_end(), -1.0, 1e-12);
  EXPECT_NEAR(second.domain_start(), 1.0, 1e-12);
  EXPECT_EQ(first.points.back(), second.points.front());
  EXPECT_LT((first.points.back().head<2>() - shift).norm(), 1e-15);
  // The cut pieces no longer share the edge; the untouched rectangle does.
  EXPECT_EQ(cut.edges, (std::vector<TrimEdgeRef>{{}, {}, {4, true}}));
  // The lobe's 8/15 (scaled) is what the loop lost, to the 1e-6 of its area that 4096 samples per span
  // leave.
  EXPECT_NEAR(before - area(cut), 8.0 / 15 * scale * scale, 1e-6 * 8.0 / 15 * scale * scale);
}

TEST(RepairTrimmingLoops, ALoopTouchingItselfAtAPoleIsNotACrossing) {
  TrimmedSurface t = dome();
  // Runs along v = 0 twice through the same point (a degenerate side), crossing nothing.
  t.loops.push_back(polyline_loop({{0.2, 0.0}, {0.5, 0.0}, {0.5, 0.0}, {0.8, 0.0}, {0.5, 0.6}}));
  EXPECT_TRUE(repair_trimming_loops(t, "face 7").empty());
}
