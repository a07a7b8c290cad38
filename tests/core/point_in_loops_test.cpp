// The one even-odd point-in-loops test: a square with a hole, whichever way its loops run, and the
// crossings of a horizontal line with the loops.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/point_in_loops.hpp"

namespace cadnurbs {
namespace {

std::vector<Eigen::Vector2d> square(double lo, double hi) { return {{lo, lo}, {hi, lo}, {hi, hi}, {lo, hi}}; }

TEST(PointInLoops, SquareWithAHoleByTheEvenOddRule) {
  for (bool reverse_hole : {false, true}) {
    auto hole = square(1, 3);
    if (reverse_hole) std::reverse(hole.begin(), hole.end());
    const PointInLoops region({square(0, 4), hole});
    EXPECT_TRUE(region.inside({0.5, 0.5}));
    EXPECT_TRUE(region.inside({3.5, 2.0}));
    EXPECT_FALSE(region.inside({2.0, 2.0}));  // in the hole
    EXPECT_FALSE(region.inside({5.0, 2.0}));  // outside
    EXPECT_FALSE(region.inside({2.0, -1.0}));
    EXPECT_EQ(region.crossings(2.0), (std::vector<double>{0, 1, 3, 4}));
    EXPECT_TRUE(region.crossings(5.0).empty());
  }
}

TEST(PointInLoops, NoLoopsMeansEverywhere) {
  const PointInLoops everywhere({});
  EXPECT_TRUE(everywhere.inside({1e9, -1e9}));
}

}  // namespace
}  // namespace cadnurbs
