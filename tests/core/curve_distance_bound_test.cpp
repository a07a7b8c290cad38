#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "core/curve_distance_bound.hpp"
#include "core/knot_insertion.hpp"
#include "test_shapes.hpp"

using namespace cadnurbs;

namespace {

// A planar polynomial curve of `order` on [0, 1] with uniform knots through `points`.
NurbsCurve planar_curve(int order, const std::vector<Eigen::Vector3d>& points) {
  NurbsCurve c;
  c.dimension = 2;
  c.order = order;
  c.points = points;
  const int spans = static_cast<int>(points.size()) - order + 1;
  c.knots.assign(order, 0.0);
  for (int i = 1; i < spans; ++i) c.knots.push_back(static_cast<double>(i) / spans);
  c.knots.insert(c.knots.end(), order, 1.0);
  return c;
}

double sampled_distance(const NurbsCurve& a, const NurbsCurve& b) {
  double d = 0;
  for (int i = 0; i <= 10000; ++i) d = std::max(d, (curve_point(a, i / 10000.0) - curve_point(b, i / 10000.0)).norm());
  return d;
}

}  // namespace

TEST(CurveDistanceBound, ATranslatedCurveIsExactlyTheTranslationAway) {
  const NurbsCurve a = planar_curve(4, {{0, 0, 0}, {1, 2, 0}, {2, -1, 0}, {3, 1, 0}, {4, 0, 0}, {5, 3, 0}});
  NurbsCurve b = refine_knots(a, {0.3, 0.7});  // other spans: the bound splits both at every breakpoint
  for (auto& p : b.points) p += Eigen::Vector3d(0.3, -0.4, 0);
  EXPECT_NEAR(curve_distance_bound(a, b), 0.5, 1e-12);
  EXPECT_NEAR(curve_distance_bound(b, a), 0.5, 1e-12);
}

TEST(CurveDistanceBound, TheSameCurveWithMoreKnotsIsNoDistanceAway) {
  const NurbsCurve a = planar_curve(3, {{0, 0, 0}, {1, 2, 0}, {2, -1, 0}, {3, 1, 0}, {4, 0, 0}});
  EXPECT_LT(curve_distance_bound(a, refine_knots(a, {0.1, 0.25, 0.25, 0.9})), 1e-12);
}

TEST(CurveDistanceBound, BoundsTheSquareAgainstTheCubeOfT) {
  // (t, t^2) against (t, t^3) on [0, 1]: the largest distance is 4/27 at t = 2/3. At degree 3 the difference
  // t^2 - t^3 has Bernstein coefficients (0, 0, 1/3, 0), so the bound on one span is 1/3.
  const NurbsCurve square = planar_curve(3, {{0, 0, 0}, {0.5, 0, 0}, {1, 1, 0}});
  const NurbsCurve cube = planar_curve(4, {{0, 0, 0}, {1.0 / 3, 0, 0}, {2.0 / 3, 0, 0}, {1, 1, 0}});
  const double bound = curve_distance_bound(square, cube);
  EXPECT_NEAR(bound, 1.0 / 3, 1e-12);
  EXPECT_GE(bound, sampled_distance(square, cube));
  EXPECT_NEAR(sampled_distance(square, cube), 4.0 / 27, 1e-6);
  // Split into 8 spans the hull closes in on the curve: the bound falls towards 4/27, never below it.
  const std::vector<double> eighths{0.125, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875};
  const double finer = curve_distance_bound(refine_knots(square, eighths), cube);
  EXPECT_LT(finer, 0.16);
  EXPECT_GE(finer, 4.0 / 27 - 1e-12);
}

TEST(CurveDistanceBound, RefusesRationalCurvesAndOtherDomains) {
  const NurbsCurve line = planar_curve(2, {{0, 0, 0}, {1, 0, 0}});
  try {
    curve_distance_bound(line, test::full_circle(1.0));
    FAIL() << "a rational curve was measured";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "curve_distance_bound: a rational curve");
  }
  NurbsCurve longer = line;
  longer.knots = {0, 0, 2, 2};
  try {
    curve_distance_bound(line, longer);
    FAIL() << "curves on different domains were measured";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "curve_distance_bound: curves on different domains");
  }
}
