// clip_loop_to_domain: loops that leave the domain cut to it as GLU draws them, against closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "core/clip_loop_to_domain.hpp"
#include "core/polygon_2d.hpp"
#include "test_shapes.hpp"

using namespace cadnurbs;

namespace {

const double kPi = 3.14159265358979323846;

// A circle of radius r about c as a 2D trimming loop, counter-clockwise (clockwise when `hole`).
TrimLoop circle_loop(const Eigen::Vector2d& c, double r, bool hole = false) {
  NurbsCurve circle = test::full_circle(r);
  circle.dimension = 2;
  for (auto& p : circle.points) p.head<2>() += c, p.y() = hole ? 2 * c.y() - p.y() : p.y();
  TrimLoop loop;
  loop.segments.emplace_back(circle);
  return loop;
}

double area(const std::vector<TrimLoop>& loops) {
  double sum = 0;
  for (const auto& loop : loops) sum += polygon_signed_area(loop_polygon(loop, 512));
  return sum;
}

double farthest_outside(const std::vector<TrimLoop>& loops, const DomainBox& b) {
  double worst = 0;
  for (const auto& loop : loops)
    for (const auto& p : loop_polygon(loop, 64))
      worst = std::max({worst, b.u0 - p.x(), p.x() - b.u1, b.v0 - p.y(), p.y() - b.v1});
  return worst;
}

TEST(ClipLoopToDomain, ACircleAboutACornerLeavesAQuarterDisc) {
  const DomainBox box{0, 1, 0, 1};
  const auto clipped = clip_loop_to_domain(circle_loop({0, 0}, 0.8), box);
  ASSERT_EQ(clipped.size(), 1u);
  EXPECT_NEAR(area(clipped), kPi * 0.64 / 4, 1e-5);
  EXPECT_LE(farthest_outside(clipped, box), 1e-12);
}

// A circle of radius 0.7 about the centre of the unit square: the disc less the four segments beyond
// the sides (they do not overlap: the corners lie 0.707 from the centre). Clockwise, it is a hole: the
// same region, clockwise.
TEST(ClipLoopToDomain, ACircleOverAllFourSidesLeavesTheDiscLessFourSegments) {
  const DomainBox box{0, 1, 0, 1};
  const double r = 0.7, d = 0.5;
  const double segment = r * r * std::acos(d / r) - d * std::sqrt(r * r - d * d);
  const double exact = kPi * r * r - 4 * segment;
  const auto outer = clip_loop_to_domain(circle_loop({0.5, 0.5}, r), box);
  ASSERT_EQ(outer.size(), 1u);
  EXPECT_NEAR(area(outer), exact, 1e-5);
  const auto hole = clip_loop_to_domain(circle_loop({0.5, 0.5}, r, true), box);
  ASSERT_EQ(hole.size(), 1u);
  EXPECT_NEAR(area(hole), -exact, 1e-5);
  EXPECT_LE(farthest_outside(hole, box), 1e-12);
}

// A thin rectangle across a narrow domain leaves two pieces: the domain cuts it in two.
TEST(ClipLoopToDomain, ALoopCrossingTheDomainTwiceLeavesTwoLoops) {
  const DomainBox box{0, 1, 0, 3};
  TrimLoop u;  // a U shape: down the left, across below the domain, up the right
  u.segments.emplace_back(Polyline2D{{{0.2, 2}, {0.2, -1}, {0.8, -1}, {0.8, 2}, {0.7, 2}, {0.7, -0.5}, {0.3, -0.5}, {0.3, 2}, {0.2, 2}}});
  const auto clipped = clip_loop_to_domain(u, box);
  ASSERT_EQ(clipped.size(), 2u);
  EXPECT_NEAR(area(clipped), 2 * 0.1 * 2, 1e-12);
}

TEST(ClipLoopToDomain, ALoopRoundTheWholeDomainIsItsBoundaryAndOneBesideItIsNothing) {
  const DomainBox box{0, 1, 0, 5};
  TrimLoop square;
  square.segments.emplace_back(Polyline2D{{{-10, -10}, {10, -10}, {10, 10}, {-10, 10}, {-10, -10}}});
  const auto whole = clip_loop_to_domain(square, box);
  ASSERT_EQ(whole.size(), 1u);
  EXPECT_DOUBLE_EQ(area(whole), 5);
  TrimLoop beside;
  beside.segments.emplace_back(Polyline2D{{{2, 0}, {3, 0}, {3, 1}, {2, 0}}});
  EXPECT_TRUE(clip_loop_to_domain(beside, box).empty());
}

}  // namespace
