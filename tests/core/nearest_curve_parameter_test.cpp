#include "core/nearest_curve_parameter.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "core/interpolate_curve.hpp"

using namespace cadnurbs;

namespace {

// The nodal cubic x = t^2 - 1, y = t (t^2 - 1), interpolated at 61 points over t in [-1.5, 1.5]: it
// passes the origin twice, at t = -1 and t = 1 (the interpolant's parameter is t).
NurbsCurve nodal_cubic() {
  std::vector<Eigen::Vector3d> points;
  std::vector<double> t;
  for (int k = 0; k <= 60; ++k) {
    const double s = -1.5 + 3.0 * k / 60;
    points.emplace_back(s * s - 1, s * (s * s - 1), 0.0);
    t.push_back(s);
  }
  return interpolate_curve(points, t, 3, 3);
}

TEST(CurveParametersNear, EveryPassOfACurveThatCrossesItself) {
  const NurbsCurve curve = nodal_cubic();
  const std::vector<double> passes = curve_parameters_near(curve, Eigen::Vector3d(0, 0, 0), 1e-6);
  ASSERT_EQ(passes.size(), 2u);
  EXPECT_NEAR(passes[0], -1.0, 1e-6);
  EXPECT_NEAR(passes[1], 1.0, 1e-6);
  // A point 0.01 off the crossing: both passes within 0.02, none within 0.001.
  const Eigen::Vector3d off(0.01, 0.0, 0.0);
  EXPECT_EQ(curve_parameters_near(curve, off, 0.02).size(), 2u);
  EXPECT_EQ(curve_parameters_near(curve, off, 0.001).size(), 0u);
  // The single nearest is one of the passes.
  const double t = nearest_curve_parameter(curve, Eigen::Vector3d(0, 0, 0));
  EXPECT_NEAR(std::abs(t), 1.0, 1e-6);
}

}  // namespace
