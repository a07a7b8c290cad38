// UnionFind: classes joined in any order number the same, by their smallest elements.
#include "core/union_find.hpp"

#include <gtest/gtest.h>

namespace cadnurbs {
namespace {

TEST(UnionFind, ClassNumbersFollowSmallestElements) {
  UnionFind a(7), b(7);
  a.unite(6, 2), a.unite(2, 4), a.unite(5, 1), a.unite(3, 3);
  b.unite(4, 6), b.unite(1, 5), b.unite(6, 2);  // the same classes joined the other way round
  const std::vector<int> expected = {0, 1, 2, 3, 2, 1, 2};  // {0}, {1,5}, {2,4,6}, {3}
  EXPECT_EQ(std::move(a).into_class_numbers(), expected);
  EXPECT_EQ(std::move(b).into_class_numbers(), expected);
}

// A chain joined from its far end makes parents several steps deep; numbering still reaches the root.
TEST(UnionFind, DeepChainsGetTheirRootsNumber) {
  const int n = 1000;
  UnionFind chain(n + 1);
  for (int x = n; x > 1; --x) chain.unite(x, x - 1);  // 1..n one class, 0 alone
  const std::vector<int> numbers = std::move(chain).into_class_numbers();
  EXPECT_EQ(numbers[0], 0);
  for (int x = 1; x <= n; ++x) ASSERT_EQ(numbers[x], 1) << x;
}

}  // namespace
}  // namespace cadnurbs
