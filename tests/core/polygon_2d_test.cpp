// 2D polygon measures against closed forms.
#include <gtest/gtest.h>

#include "core/polygon_2d.hpp"

namespace cadnurbs {
namespace {

TEST(Polygon2d, ShoelaceAreaIsSignedByOrientation) {
  const std::vector<Eigen::Vector2d> rectangle = {{0, 0}, {3, 0}, {3, 2}, {0, 2}};
  EXPECT_DOUBLE_EQ(polygon_signed_area(rectangle), 6.0);
  const std::vector<Eigen::Vector2d> clockwise(rectangle.rbegin(), rectangle.rend());
  EXPECT_DOUBLE_EQ(polygon_signed_area(clockwise), -6.0);
  EXPECT_DOUBLE_EQ(polygon_signed_area({{1, 1}, {2, 2}}), 0.0);
}

TEST(Polygon2d, ConvexCornerTurnsLeftOrStraightWithinTheTolerance) {
  const Eigen::Vector2d a(0, 0), c(2, 0);
  EXPECT_TRUE(convex_corner(a, {1, -1}, c, 0.0));     // left turn (counter-clockwise)
  EXPECT_FALSE(convex_corner(a, {1, 1}, c, 0.5));     // right turn by 1 off the line a-c
  EXPECT_TRUE(convex_corner(a, {1, 0.4}, c, 0.5));    // right by 0.4: straight within 0.5
  EXPECT_FALSE(convex_corner(a, {1, 0.6}, c, 0.5));
  EXPECT_TRUE(convex_corner(a, {5, 5}, a, 0.0));      // a = c
}

}  // namespace
}  // namespace cadnurbs
