// orient_loops: outer boundaries counter-clockwise, holes clockwise, by containment alone; a loop it
// turns round also turns its edge references.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/loop_orientation.hpp"

namespace cadnurbs {
namespace {

TrimLoop square(double lo, double hi, bool counter_clockwise, int first_edge) {
  std::vector<Eigen::Vector2d> p{{lo, lo}, {hi, lo}, {hi, hi}, {lo, hi}};
  if (!counter_clockwise) std::reverse(p.begin(), p.end());
  TrimLoop loop;
  for (size_t k = 0; k < p.size(); ++k) {
    loop.segments.emplace_back(Polyline2D{{p[k], p[(k + 1) % p.size()]}});
    loop.edges.push_back({first_edge + static_cast<int>(k), false});
  }
  return loop;
}

TEST(LoopOrientation, OuterCounterClockwiseHolesClockwise) {
  // Outer clockwise (wrong), hole clockwise (right), an island in the hole clockwise (wrong: it is an
  // outer boundary again).
  std::vector<TrimLoop> loops{square(0, 10, false, 0), square(2, 8, false, 4), square(4, 6, false, 8)};
  orient_loops(loops);
  EXPECT_GT(loop_signed_area(loops[0]), 0);
  EXPECT_LT(loop_signed_area(loops[1]), 0);
  EXPECT_GT(loop_signed_area(loops[2]), 0);
  // The turned loops' edge references run backwards and are marked reversed; the hole is untouched.
  EXPECT_EQ(loops[0].edges.front().edge, 3);
  EXPECT_TRUE(loops[0].edges.front().reversed);
  EXPECT_EQ(loops[1].edges.front().edge, 4);
  EXPECT_FALSE(loops[1].edges.front().reversed);
  EXPECT_EQ(loops[2].edges.front().edge, 11);
  EXPECT_TRUE(loops[2].edges.front().reversed);
}

TEST(LoopOrientation, LoopsInTheRightDirectionStayAsTheyAre) {
  const std::vector<TrimLoop> given{square(0, 10, true, 0), square(2, 8, false, 4)};
  std::vector<TrimLoop> loops = given;
  orient_loops(loops);
  for (size_t l = 0; l < loops.size(); ++l) EXPECT_EQ(loops[l].edges, given[l].edges) << l;
}

}  // namespace
}  // namespace cadnurbs
