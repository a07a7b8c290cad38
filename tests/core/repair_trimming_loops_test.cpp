// repair_trimming_loops: the faults of real files (a loop bounding no area, a loop a little outside the
// domain, a loop crossing itself) repaired or refused, with the exact messages.
#include <gtest/gtest.h>

#include "core/geometry_error.hpp"
#include "core/nurbs_surface.hpp"
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
  EXPECT_EQ(refusal(t), "face 7: trimming loop 0 crosses itself");
}

TEST(RepairTrimmingLoops, ALoopTouchingItselfAtAPoleIsNotACrossing) {
  TrimmedSurface t = dome();
  // Runs along v = 0 twice through the same point (a degenerate side), crossing nothing.
  t.loops.push_back(polyline_loop({{0.2, 0.0}, {0.5, 0.0}, {0.5, 0.0}, {0.8, 0.0}, {0.5, 0.6}}));
  EXPECT_TRUE(repair_trimming_loops(t, "face 7").empty());
}
