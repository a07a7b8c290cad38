#include <gtest/gtest.h>

#include <random>

#include "core/geometry_error.hpp"
#include "core/nurbs_curve.hpp"
#include "test_shapes.hpp"

using namespace cadnurbs;

TEST(Curve, QuarterCircleIsExactlyRound) {
  const NurbsCurve arc = test::quarter_circle(2.5);
  validate(arc, "arc");
  for (int i = 0; i <= 1000; ++i) EXPECT_NEAR(curve_point(arc, i / 1000.0).norm(), 2.5, 1e-12);
  EXPECT_NEAR((curve_point(arc, 1.0) - Eigen::Vector3d(0, 2.5, 0)).norm(), 0.0, 1e-15);
}

TEST(Curve, FullCircleIsExactlyRound) {
  const NurbsCurve circle = test::full_circle(7.0);
  validate(circle, "circle");
  for (int i = 0; i <= 1000; ++i) EXPECT_NEAR(curve_point(circle, 4.0 * i / 1000.0).norm(), 7.0, 1e-12);
}

TEST(Curve, DerivativesMatchCentralDifferences) {
  NurbsCurve c;
  c.order = 4;
  c.knots = {0, 0, 0, 0, 0.3, 0.6, 1, 1, 1, 1};
  c.points = {{0, 0, 0}, {1, 2, 0}, {2, -1, 1}, {3, 3, 2}, {4, 0, 0}, {5, 1, -1}};
  c.weights = {1, 0.5, 2, 1, 0.7, 1};
  validate(c, "c");
  const double h = 1e-5;
  for (double t : {0.1, 0.25, 0.45, 0.8, 0.95}) {
    const auto d = curve_derivatives(c, t, 2);
    const Eigen::Vector3d fd1 = (curve_point(c, t + h) - curve_point(c, t - h)) / (2 * h);
    const Eigen::Vector3d fd2 = (curve_point(c, t + h) - 2 * curve_point(c, t) + curve_point(c, t - h)) / (h * h);
    EXPECT_LT((d[1] - fd1).norm(), 1e-6 * (1 + d[1].norm())) << t;
    EXPECT_LT((d[2] - fd2).norm(), 1e-3 * (1 + d[2].norm())) << t;
  }
}

TEST(Curve, ReversedTracesTheSamePoints) {
  const NurbsCurve c = test::full_circle(1.0);
  const NurbsCurve r = reversed(c);
  for (double t = 0; t <= 4.0; t += 0.1) EXPECT_LT((curve_point(c, t) - curve_point(r, 4.0 - t)).norm(), 1e-14);
}

TEST(Curve, RefusesNonPositiveWeight) {
  NurbsCurve c = test::quarter_circle(1);
  c.weights[1] = 0.0;
  try {
    validate(c, "profile arc");
    FAIL() << "accepted a zero weight";
  } catch (const GeometryError& e) {
    EXPECT_STREQ(e.what(), "profile arc: weight 1 is 0.000000; weights must be positive");
  }
}

TEST(Curve, RefusesDecreasingKnots) {
  NurbsCurve c = test::quarter_circle(1);
  c.knots = {0, 0, 0.5, 0.2, 1, 1};
  EXPECT_THROW(validate(c, "c"), GeometryError);
  try {
    validate(c, "c");
  } catch (const GeometryError& e) {
    EXPECT_EQ(e.reason(), "knot 3 (0.2) is smaller than knot 2 (0.5); knots must not decrease");
  }
}

TEST(Curve, RefusesTooFewControlPoints) {
  NurbsCurve c;
  c.order = 4;
  c.points = {{0, 0, 0}, {1, 0, 0}};
  c.knots = {0, 0, 0, 0, 1, 1};
  try {
    validate(c, "rail");
    FAIL();
  } catch (const GeometryError& e) {
    EXPECT_STREQ(e.what(), "rail: 2 control points are too few for order 4 (need at least 4)");
  }
}

TEST(Curve, RefusesWeightCountMismatch) {
  NurbsCurve c = test::quarter_circle(1);
  c.weights.pop_back();
  try {
    validate(c, "arc");
    FAIL();
  } catch (const GeometryError& e) {
    EXPECT_STREQ(e.what(), "arc: 2 weights for 3 control points");
  }
}
