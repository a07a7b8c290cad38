#include <gtest/gtest.h>

#include <cmath>

#include "core/knot_insertion.hpp"
#include "core/refit_cubic_within.hpp"
#include "test_shapes.hpp"

using namespace cadnurbs;

namespace {

// Distance from each of 4,000 points of `a` to the nearest of 40,000 points of `b`, the largest: a sampled
// one-sided Hausdorff distance, within b's sample spacing of the true one.
double sampled_reach(const NurbsCurve& a, const NurbsCurve& b) {
  std::vector<Eigen::Vector3d> dense;
  for (int i = 0; i <= 40000; ++i)
    dense.push_back(curve_point(b, b.domain_start() + (b.domain_end() - b.domain_start()) * i / 40000.0));
  double reach = 0;
  for (int i = 0; i <= 4000; ++i) {
    const Eigen::Vector3d p = curve_point(a, a.domain_start() + (a.domain_end() - a.domain_start()) * i / 4000.0);
    double nearest = INFINITY;
    for (const auto& q : dense) nearest = std::min(nearest, (p - q).squaredNorm());
    reach = std::max(reach, std::sqrt(nearest));
  }
  return reach;
}

// A pcurve as a kernel approximates one: degree 7, 64 control points along a wave, uneven knots (the
// speed changes fivefold along it), on the domain [0.3, 2.9].
NurbsCurve approximated_wave() {
  NurbsCurve c;
  c.dimension = 2;
  c.order = 8;
  const int count = 64, spans = count - c.order + 1;
  c.knots.assign(c.order, 0.3);
  for (int i = 1; i < spans; ++i) {
    const double s = static_cast<double>(i) / spans;
    c.knots.push_back(0.3 + 2.6 * (s + 0.35 * s * (1 - s)));
  }
  c.knots.insert(c.knots.end(), c.order, 2.9);
  for (int i = 0; i < count; ++i) {
    const double x = 4.0 * i / (count - 1);
    c.points.emplace_back(x, 0.5 * std::sin(2.0 * x) + 0.1 * x * x, 0.0);
  }
  return c;
}

}  // namespace

TEST(RefitCubicWithin, AStraightCubicWithManyKnotsIsOneSpan) {
  NurbsCurve line;
  line.dimension = 2;
  line.order = 4;
  line.knots = {0, 0, 0, 0, 1, 1, 1, 1};
  line.points = {{1, 1, 0}, {2, 1.5, 0}, {3, 2, 0}, {4, 2.5, 0}};
  std::vector<double> knots;
  for (int i = 1; i < 30; ++i) knots.push_back(i / 30.0);
  const NurbsCurve many = refine_knots(line, knots);
  const std::optional<NurbsCurve> fit = refit_cubic_within(many, 1e-9);
  ASSERT_TRUE(fit);
  EXPECT_EQ(fit->count(), 4);
  EXPECT_EQ(fit->knots, (std::vector<double>{0, 0, 0, 0, 1, 1, 1, 1}));
  EXPECT_EQ(fit->points.front(), many.points.front());
  EXPECT_EQ(fit->points.back(), many.points.back());
  EXPECT_LT(sampled_reach(*fit, many), 1e-9);
}

TEST(RefitCubicWithin, AnApproximatedWaveGetsFewerPointsWithinTheTolerance) {
  const NurbsCurve wave = approximated_wave();
  for (double tolerance : {1e-2, 3e-3, 1e-3}) {
    const std::optional<NurbsCurve> fit = refit_cubic_within(wave, tolerance);
    ASSERT_TRUE(fit) << tolerance;
    validate(*fit, "fit");
    EXPECT_LT(fit->count(), wave.count()) << tolerance;
    // Whole-number knots from 0 to a power of two, the ends where the wave's are, bit for bit.
    EXPECT_EQ(fit->knots.front(), 0.0);
    EXPECT_EQ(std::exp2(std::round(std::log2(fit->knots.back()))), fit->knots.back());
    for (double k : fit->knots) EXPECT_EQ(k, std::round(k));
    EXPECT_EQ(fit->points.front(), wave.points.front());
    EXPECT_EQ(fit->points.back(), wave.points.back());
    // Both ways within the tolerance (sampled, so with the samples' spacing of a few 1e-4 as slack below).
    EXPECT_LE(sampled_reach(*fit, wave), tolerance) << tolerance;
    EXPECT_LE(sampled_reach(wave, *fit), tolerance + 3e-4) << tolerance;
  }
  // A looser tolerance never needs more points.
  EXPECT_LE(refit_cubic_within(wave, 1e-2)->count(), refit_cubic_within(wave, 1e-3)->count());
  EXPECT_LE(refit_cubic_within(wave, 1e-2)->count(), 20);
}

TEST(RefitCubicWithin, RefusesRationalCurvesAndNoTolerance) {
  EXPECT_FALSE(refit_cubic_within(test::full_circle(1.0), 1.0));
  EXPECT_FALSE(refit_cubic_within(approximated_wave(), 0.0));
}
