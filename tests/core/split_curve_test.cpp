// split_curve: both halves trace the curve exactly over their part of the domain.
#include <gtest/gtest.h>

#include "core/geometry_error.hpp"
#include "core/split_curve.hpp"
#include "test_shapes.hpp"

namespace cadnurbs {
namespace {

void expect_traces(const NurbsCurve& part, const NurbsCurve& whole, double t0, double t1) {
  EXPECT_DOUBLE_EQ(part.domain_start(), t0);
  EXPECT_DOUBLE_EQ(part.domain_end(), t1);
  for (int k = 0; k <= 20; ++k) {
    const double t = t0 + (t1 - t0) * k / 20;
    EXPECT_LT((curve_point(part, t) - curve_point(whole, t)).norm(), 1e-12) << "t=" << t;
  }
}

TEST(SplitCurve, RationalCircleInsideASpan) {
  const NurbsCurve circle = test::full_circle(2.0);
  const auto [before, after] = split_curve(circle, 1.5);
  expect_traces(before, circle, 0.0, 1.5);
  expect_traces(after, circle, 1.5, 4.0);
  EXPECT_LT((before.points.back() - after.points.front()).norm(), 1e-15);
  EXPECT_NEAR(curve_point(after, 1.5).norm(), 2.0, 1e-12);  // still on the circle
  EXPECT_EQ(before.points.size() + after.points.size(), circle.points.size() + 2 + 1);  // 2 inserted, 1 shared
}

TEST(SplitCurve, AtAKnotOfFullMultiplicityNothingIsInserted) {
  const NurbsCurve circle = test::full_circle(1.0);
  const auto [before, after] = split_curve(circle, 2.0);  // the double knot: the point (-1, 0)
  EXPECT_EQ(before.points.size(), 5u);
  EXPECT_EQ(after.points.size(), 5u);
  EXPECT_LT((before.points.back() - Eigen::Vector3d(-1, 0, 0)).norm(), 1e-15);
  expect_traces(before, circle, 0.0, 2.0);
  expect_traces(after, circle, 2.0, 4.0);
}

TEST(SplitCurve, RefusesTheDomainEnds) {
  const NurbsCurve circle = test::full_circle(1.0);
  EXPECT_THROW(split_curve(circle, 0.0), GeometryError);
  EXPECT_THROW(split_curve(circle, 4.0), GeometryError);
}

}  // namespace
}  // namespace cadnurbs
