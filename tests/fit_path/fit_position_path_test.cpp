// analysis/fitting/fit_position_path: keyframe paths as one polynomial NURBS curve within a deviation, checked
// at every key and halfway between keys, and the error bound against closed forms.
#include "analysis/fitting/fit_position_path.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/geometry_error.hpp"
#include "core/knot_insertion.hpp"
#include "fit_path/path_shapes.hpp"

namespace cadnurbs::test {
namespace {


void expect_clamped_on_unit_interval(const NurbsCurve& curve) {
  EXPECT_FALSE(curve.is_rational());
  for (int i = 0; i < curve.order; ++i) {
    EXPECT_EQ(curve.knots[i], 0.0);
    EXPECT_EQ(curve.knots[curve.knots.size() - 1 - i], 1.0);
  }
}

struct SmoothCase {
  const char* name;
  KeyframePath path;
  double deviation;
};

TEST(FitPositionPath, SmoothPathsFitWithinTheDeviationWithATenthOfTheKeys) {
  const std::vector<SmoothCase> cases = {
      {"circle, 1,000 keys", circle_path(1000, 10.0), 0.01},
      {"helix, 600 keys", helix_path(600, 5.0, 3.0, 2.0), 0.01},
      {"figure-eight, 800 uneven keys", figure_eight_path(800, 20.0), 0.01},
  };
  for (const SmoothCase& c : cases) {
    const PositionPathFit fit = fit_position_path(c.path.keys, c.path.values, c.deviation);
    expect_clamped_on_unit_interval(fit.curve);
    EXPECT_LE(fit.max_error, c.deviation) << c.name;
    EXPECT_LE(sampled_path_error(fit.curve, c.path), fit.max_error + 1e-12) << c.name << ": the bound is below a sample";
    EXPECT_LE(fit.curve.count() * 10, static_cast<int>(c.path.keys.size())) << c.name << ": " << fit.curve.count();
    EXPECT_EQ(curve_point(fit.curve, 0.0), c.path.values.front()) << c.name << ": starts where the path does";
    EXPECT_EQ(curve_point(fit.curve, 1.0), c.path.values.back()) << c.name << ": ends where the path does";
    std::cout << c.name << ": " << fit.curve.count() << " control points, bound " << fit.max_error << "\n";
  }
}

TEST(FitPositionPath, ARecordedPathWithNoiseOfATenthOfTheDeviationStaysWithinIt) {
  const double deviation = 0.01;
  const KeyframePath path = noisy_circle_path(1000, 10.0, deviation / 10);
  const PositionPathFit fit = fit_position_path(path.keys, path.values, deviation);
  EXPECT_LE(fit.max_error, deviation);
  EXPECT_LE(sampled_path_error(fit.curve, path), deviation);
  EXPECT_LT(fit.curve.count(), 1000 / 4) << "the noise must not be followed key by key";
}

TEST(FitPositionPath, KeysInsideTheUnitIntervalGetConstantEnds) {
  // Keys on [0.2, 0.7]: before 0.2 the interpolator gives the first value, after 0.7 the last.
  KeyframePath path = circle_path(200, 3.0);
  for (double& k : path.keys) k = 0.2 + 0.5 * k;
  const PositionPathFit fit = fit_position_path(path.keys, path.values, 0.001);
  expect_clamped_on_unit_interval(fit.curve);
  EXPECT_LE(fit.max_error, 0.001);
  for (double t : {0.0, 0.05, 0.1999}) EXPECT_LE((curve_point(fit.curve, t) - path.values.front()).norm(), 0.001) << t;
  for (double t : {0.7001, 0.9, 1.0}) EXPECT_LE((curve_point(fit.curve, t) - path.values.back()).norm(), 0.001) << t;
}

TEST(FitPositionPath, OneKeyOrEqualKeysGiveAConstantCurve) {
  const Eigen::Vector3d p(1, 2, 3);
  const PositionPathFit one = fit_position_path({0.4}, {p}, 0.01);
  EXPECT_EQ(one.max_error, 0.0);
  EXPECT_EQ(curve_point(one.curve, 0.9), p);
  const PositionPathFit twice = fit_position_path({0.4, 0.4}, {p, p}, 0.01);
  EXPECT_EQ(twice.max_error, 0.0);
}

TEST(FitPositionPath, RefusesWhatNoInterpolatorMeans) {
  const Eigen::Vector3d a(0, 0, 0), b(1, 0, 0);
  const auto reason = [](const std::vector<double>& keys, const std::vector<Eigen::Vector3d>& values) {
    try {
      fit_position_path(keys, values, 0.01);
    } catch (const GeometryError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(reason({-0.1, 1}, {a, b}), "PositionInterpolator: key 0 (-0.1) is outside [0, 1]");
  EXPECT_EQ(reason({0, 0.6, 0.5}, {a, b, a}), "PositionInterpolator: key 2 is smaller than the key before it");
  EXPECT_EQ(reason({0, 1}, {a}), "PositionInterpolator: 2 keys but 1 key values");
  EXPECT_EQ(reason({}, {}), "PositionInterpolator: no keys");
}

// A half circle of radius 1 in two quarters (21 keys each) meeting at fraction 0.5, the key repeated there.
// With the second circle moved 1 away it is a jump: held by a knot of full multiplicity at the key, the
// curve on each side within D of that side's path (the bound takes each side's limit). Moved 0.001 away
// at D = 0.01 (keys written with few decimals) it is no jump: one continuous curve.
TEST(FitPositionPath, AJumpIsAKnotOfFullMultiplicityAndANearRepeatIsNone) {
  const auto two_arcs = [](double apart, std::vector<double>& keys, std::vector<Eigen::Vector3d>& values) {
    keys.clear(), values.clear();
    for (int half = 0; half < 2; ++half)
      for (int i = 0; i <= 20; ++i) {
        const double angle = 0.5 * 3.14159265358979 * (half + i / 20.0);
        keys.push_back(0.5 * half + 0.5 * i / 20.0);
        values.emplace_back(std::cos(angle) + half * apart, std::sin(angle), 0);
      }
  };
  std::vector<double> keys;
  std::vector<Eigen::Vector3d> values;
  two_arcs(1.0, keys, values);
  const PositionPathFit jump = fit_position_path(keys, values, 0.01);
  EXPECT_LE(jump.max_error, 0.01);
  EXPECT_EQ(std::count(jump.curve.knots.begin(), jump.curve.knots.end(), 0.5), jump.curve.order);
  EXPECT_LE((curve_point(jump.curve, 0.5 - 1e-12) - values[20]).norm(), 0.01);
  EXPECT_LE((curve_point(jump.curve, 0.5) - values[21]).norm(), 0.01);
  two_arcs(0.001, keys, values);
  const PositionPathFit near = fit_position_path(keys, values, 0.01);
  EXPECT_LE(near.max_error, 0.01);
  EXPECT_LT(std::count(near.curve.knots.begin(), near.curve.knots.end(), 0.5), near.curve.order);
  // The bound measured the near repeat against both of its values.
  const Eigen::Vector3d at = curve_point(near.curve, 0.5);
  EXPECT_GE(near.max_error, std::max((at - values[20]).norm(), (at - values[21]).norm()) - 1e-12);
}

TEST(PathErrorBound, IsZeroForThePathItselfAndTheOffsetForAShiftedCopy) {
  // The degree-1 B-spline through the keys is the path; the same shifted by 0.5 is 0.5 away everywhere.
  const KeyframePath path = figure_eight_path(50, 4.0);
  NurbsCurve linear;
  linear.order = 2;
  linear.points = path.values;
  linear.knots = {0.0};
  for (double k : path.keys) linear.knots.push_back(k);
  linear.knots.push_back(1.0);
  EXPECT_LE(path_error_bound(linear, path.keys, path.values), 1e-12);
  // With knots inserted it is the same curve in more pieces: still within round-off.
  const NurbsCurve refined = refine_knots(linear, {0.3, 0.31, 0.77});
  EXPECT_LE(path_error_bound(refined, path.keys, path.values), 1e-12);
  NurbsCurve shifted = linear;
  for (auto& p : shifted.points) p.z() += 0.5;
  EXPECT_NEAR(path_error_bound(shifted, path.keys, path.values), 0.5, 1e-12);
}

TEST(PathErrorBound, BoundsTheTrueMaximumFromAboveAndNearly) {
  // A cubic against a straight two-key path: the bound is at least every sampled distance and within
  // a few per cent of the largest (the Bézier hull of one span).
  NurbsCurve curve;
  curve.order = 4;
  curve.knots = {0, 0, 0, 0, 1, 1, 1, 1};
  curve.points = {{0, 0, 0}, {1, 1, 0}, {2, 1, 0}, {3, 0, 0}};
  const std::vector<double> keys = {0, 1};
  const std::vector<Eigen::Vector3d> values = {{0, 0, 0}, {3, 0, 0}};
  const double bound = path_error_bound(curve, keys, values);
  double sampled = 0;
  for (int i = 0; i <= 1000; ++i) {
    const double t = i / 1000.0;
    sampled = std::max(sampled, (curve_point(curve, t) - Eigen::Vector3d(3 * t, 0, 0)).norm());
  }
  EXPECT_NEAR(sampled, 0.75, 1e-9);  // y(t) = 3t(1-t), x(t) = 3t: the distance is y, 0.75 at t = 1/2
  EXPECT_GE(bound, sampled);
  EXPECT_LE(bound, 1.0 + 1e-12);  // the hull's control points: (0,1,0) and (0,1,0) off the line
}

}  // namespace
}  // namespace cadnurbs::test
