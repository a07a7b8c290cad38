#include <gtest/gtest.h>

#include <numeric>

#include "core/knot_vector.hpp"

using namespace cadnurbs;

TEST(KnotVector, AcceptsClampedVector) { EXPECT_EQ(knot_vector_fault({0, 0, 0, 0.5, 1, 1, 1}, 3, 4), ""); }

TEST(KnotVector, NamesWrongCount) {
  EXPECT_EQ(knot_vector_fault({0, 0, 0, 1, 1}, 3, 3), "5 knots given, but 3 control points of order 3 need 6");
}

TEST(KnotVector, NamesDecreasingKnot) {
  EXPECT_EQ(knot_vector_fault({0, 0, 0, 0.7, 0.5, 1, 1, 1}, 3, 5),
            "knot 4 (0.5) is smaller than knot 3 (0.7); knots must not decrease");
}

TEST(KnotVector, NamesTooFewControlPoints) {
  EXPECT_EQ(knot_vector_fault({0, 0, 1, 1}, 3, 1), "1 control points are too few for order 3 (need at least 3)");
}

TEST(KnotVector, NamesExcessMultiplicity) {
  EXPECT_EQ(knot_vector_fault({0, 0, 0, 0.5, 0.5, 0.5, 0.5, 1, 1, 1}, 3, 7),
            "knot value 0.5 is repeated 4 times, more than the order 3");
}

TEST(KnotVector, BasisFunctionsSumToOne) {
  const std::vector<double> knots = {0, 0, 0, 0, 0.2, 0.5, 0.5, 0.9, 1, 1, 1, 1};
  for (double t = 0; t <= 1.0; t += 0.013) {
    const int span = find_knot_span(knots, 4, 8, t);
    ASSERT_LE(knots[span], t);
    const auto d = basis_function_derivatives(knots, 4, span, t, 2);
    EXPECT_NEAR(std::accumulate(d[0].begin(), d[0].end(), 0.0), 1.0, 1e-14);
    EXPECT_NEAR(std::accumulate(d[1].begin(), d[1].end(), 0.0), 0.0, 1e-11);
  }
}

TEST(KnotVector, SpanAtDomainEndIsLastNonEmpty) {
  const std::vector<double> knots = {0, 0, 0, 1, 2, 2, 2};
  EXPECT_EQ(find_knot_span(knots, 3, 4, 2.0), 3);
  EXPECT_EQ(find_knot_span(knots, 3, 4, 0.0), 2);
}

TEST(KnotVector, DistinctKnotsDomainBreaksAndC0Knots) {
  // Cubic (order 4), 8 control points, unclamped at the start: the domain is [knot 3, knot 8] = [1, 5].
  const std::vector<double> knots = {0, 0.5, 1, 1, 2, 3, 3, 3, 5, 6, 6, 6};
  EXPECT_EQ(distinct_knots(knots), (std::vector<double>{0, 0.5, 1, 2, 3, 5, 6}));
  EXPECT_EQ(domain_breaks(knots, 4, 8), (std::vector<double>{1, 2, 3, 5}));
  // Only 3 (multiplicity 3 = degree) is a corner; 1 is a domain end, 2 is simple.
  EXPECT_EQ(c0_knots(knots, 4, 8), (std::vector<double>{3}));
  // A clamped quadratic circle: every double knot inside is C0.
  EXPECT_EQ(c0_knots({0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4}, 3, 9), (std::vector<double>{1, 2, 3}));
  EXPECT_TRUE(c0_knots({0, 0, 1, 1}, 2, 2).empty());
}
