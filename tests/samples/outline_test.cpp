#include <gtest/gtest.h>

#include <cmath>

#include "samples/outline.hpp"

using namespace cadnurbs;

TEST(Outline, ArcCentreAndRadiusFromChordAndSweep) {
  const Outline o = parse_outline("start 0 0\narc 10 10 90\n", "t");
  ASSERT_EQ(o.segments.size(), 1u);
  EXPECT_NEAR(o.segments[0].radius, 10.0, 1e-12);
  EXPECT_NEAR((o.segments[0].centre - Eigen::Vector2d(0, 10)).norm(), 0.0, 1e-12);
}

TEST(Outline, NurbsArcsAreExactAndJoinedByDoubleKnots) {
  const Outline o = parse_outline("start -5 0\nline 0 0\narc 20 20 90\narc 40 40 -90\n", "t");
  const NurbsCurve c = outline_to_nurbs(o);
  validate(c, "c");
  EXPECT_EQ(c.knots, (std::vector<double>{0, 0, 0, 1, 1, 2, 2, 3, 3, 3}));
  EXPECT_NEAR(c.weights[3], std::cos(M_PI / 4), 1e-15);
  for (int i = 0; i <= 100; ++i) {
    const Eigen::Vector3d p = curve_point(c, 1.0 + i / 100.0);
    EXPECT_NEAR((p.head<2>() - Eigen::Vector2d(0, 20)).norm(), 20.0, 1e-12);
  }
}

TEST(Outline, ArcsAbove90DegreesAreSplit) {
  const Outline o = parse_outline("start 10 0\narc -10 0 180\n", "t");
  const NurbsCurve c = outline_to_nurbs(o);
  EXPECT_EQ(c.count(), 5);
  for (int i = 0; i <= 100; ++i) EXPECT_NEAR(curve_point(c, 2.0 * i / 100.0).norm(), 10.0, 1e-12);
}

TEST(Outline, RefusesUnknownStatementWithLineNumber) {
  try {
    parse_outline("start 0 0\n\nlin 1 1\n", "path.txt");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "path.txt: line 3: unknown statement 'lin'");
  }
}

TEST(Outline, RefusesCornerInAPath) {
  const Outline o = parse_outline("start 0 0\nline 10 0\nline 10 10\n", "path.txt");
  try {
    require_smooth(o, "path.txt");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "path.txt: segment 2 turns 90 degrees from segment 1; a swept path must be smooth");
  }
}

TEST(Outline, ChordRuleBoundsTheSagitta) {
  const Outline o = parse_outline("start 50 0\narc 0 50 90\n", "t");
  for (double d : {1.0, 0.1, 0.01}) {
    const auto pts = sample_outline(o, d);
    double worst = 0;
    for (size_t i = 0; i + 1 < pts.size(); ++i) {
      const Eigen::Vector2d mid = 0.5 * (pts[i].point + pts[i + 1].point);
      worst = std::max(worst, 50.0 - mid.norm());
    }
    EXPECT_LE(worst, d + 1e-12);
    EXPECT_GT(worst, 0.25 * d);  // not needlessly fine
  }
}
