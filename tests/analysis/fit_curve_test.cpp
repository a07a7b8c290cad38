// fit_curve and its parts: the conjugate-gradient minimiser with constraints, the reduced energy's
// gradient against finite differences, and fits of generated animation paths within a deviation D.
#include "analysis/fitting/fit_curve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

#include "analysis/fitting/curve_fit_energy.hpp"
#include "analysis/fitting/polak_ribiere.hpp"
#include "core/knot_vector.hpp"

namespace cadnurbs {
namespace {

// ---- the minimiser -----------------------------------------------------------------------------

double rosenbrock(const Eigen::VectorXd& x, Eigen::VectorXd* gradient) {
  const double a = 1 - x[0], b = x[1] - x[0] * x[0];
  if (gradient) {
    gradient->resize(2);
    (*gradient)[0] = -2 * a - 400 * x[0] * b;
    (*gradient)[1] = 200 * b;
  }
  return a * a + 100 * b * b;
}

TEST(PolakRibiere, FindsTheRosenbrockMinimum) {
  PolakRibiereOptions options;
  options.max_iterations = 2000;
  const PolakRibiereResult result = minimise_polak_ribiere(rosenbrock, Eigen::Vector2d(-1.2, 1.0), {}, options);
  EXPECT_TRUE(result.converged);
  EXPECT_NEAR(result.x[0], 1.0, 1e-4);
  EXPECT_NEAR(result.x[1], 1.0, 1e-4);
  EXPECT_LT(result.energy, 1e-8);
}

// Rosenbrock with the hard constraint x0 <= 0.5 kept by the hooks: the minimum is on the bound,
// (0.5, 0.25), and no iterate ever leaves the feasible side.
TEST(PolakRibiere, KeepsAHardBound) {
  FeasibilityHooks hooks;
  hooks.max_step = [](const Eigen::VectorXd& x, const Eigen::VectorXd& d) {
    return d[0] > 0 ? (0.5 - x[0]) / d[0] : std::numeric_limits<double>::infinity();
  };
  hooks.adjust_direction = [](const Eigen::VectorXd& x, Eigen::VectorXd& d) {
    if (x[0] >= 0.5 - 1e-12 && d[0] > 0) d[0] = 0;
  };
  int iterates = 0;
  double largest = -1e300;
  hooks.on_iterate = [&](const Eigen::VectorXd& x) {
    ++iterates;
    largest = std::max(largest, x[0]);
  };
  PolakRibiereOptions options;
  options.max_iterations = 2000;
  const PolakRibiereResult result = minimise_polak_ribiere(rosenbrock, Eigen::Vector2d(-1.2, 1.0), hooks, options);
  EXPECT_NEAR(result.x[0], 0.5, 1e-6);
  EXPECT_NEAR(result.x[1], 0.25, 1e-5);
  EXPECT_LE(largest, 0.5);
  EXPECT_EQ(iterates, result.iterations + 1);
}

// On a convex quadratic in 30 unknowns, conjugate gradient with exact-enough line searches ends in
// about as many iterations as unknowns (steepest descent would need hundreds at this conditioning).
TEST(PolakRibiere, ConvergesOnAQuadraticInAboutNIterations) {
  const int n = 30;
  Eigen::VectorXd diagonal(n), target(n);
  for (int i = 0; i < n; ++i) diagonal[i] = 1.0 + 99.0 * i / (n - 1), target[i] = std::sin(i);
  auto quadratic = [&](const Eigen::VectorXd& x, Eigen::VectorXd* gradient) {
    const Eigen::VectorXd r = x - target;
    if (gradient) *gradient = diagonal.cwiseProduct(r);
    return 0.5 * r.dot(diagonal.cwiseProduct(r));
  };
  PolakRibiereOptions options;
  options.max_iterations = 500;
  const PolakRibiereResult result = minimise_polak_ribiere(quadratic, Eigen::VectorXd::Zero(n), {}, options);
  EXPECT_LT((result.x - target).norm(), 1e-4);
  EXPECT_LE(result.iterations, 3 * n);
}

// ---- the reduced energy's gradient -------------------------------------------------------------

TEST(CurveFitEnergy, GradientMatchesCentralDifferences) {
  // A wavy space curve sampled unevenly; a rational cubic with uneven knots and weights.
  std::vector<double> parameters;
  std::vector<Eigen::Vector3d> points;
  for (int j = 0; j < 200; ++j) {
    const double t = std::pow(j / 199.0, 1.3);
    parameters.push_back(t);
    points.emplace_back(std::cos(5 * t), std::sin(7 * t), t * t);
  }
  const int order = 4, count = 9;
  std::vector<double> knots = {0, 0, 0, 0, 0.13, 0.3, 0.42, 0.61, 0.8, 1, 1, 1, 1};
  std::vector<double> weights = {1.0, 0.9, 1.2, 1.1, 0.8, 1.0, 1.3, 0.95, 1.0};
  for (const double minimum_gap : {1e-4, 0.04}) {  // 0.04: spans up to 0.16 are crowded (Simpson's rule)
    CurveFitEnergyTerms terms;
    terms.fairness = 1e-3;
    terms.knot_spread = 1e-2;
    terms.weight_pull = 1e-2;
    terms.minimum_gap = minimum_gap;
    terms.scale = 0.5;
    const CurveFitEvaluation at = evaluate_curve_fit_energy(parameters, points, order, knots, weights, terms, true);
    ASSERT_TRUE(std::isfinite(at.energy));
    // The energy's central difference in knot i (in_knots) or weight i, the rest held.
    auto central_difference = [&](bool in_knots, int i) {
      const double h = 1e-6;
      std::vector<double> k = knots, w = weights;
      double& value = in_knots ? k[i] : w[i];
      value += h;
      const double up = evaluate_curve_fit_energy(parameters, points, order, k, w, terms, false).energy;
      value -= 2 * h;
      const double down = evaluate_curve_fit_energy(parameters, points, order, k, w, terms, false).energy;
      return (up - down) / (2 * h);
    };
    for (int i = order; i < count; ++i) {
      EXPECT_NEAR(at.knot_gradient[i], central_difference(true, i), 1e-6 * std::max(1.0, std::abs(at.knot_gradient[i])))
          << "knot " << i << ", gap " << minimum_gap;
    }
    for (int i = 0; i < count; ++i) {
      EXPECT_NEAR(at.weight_gradient[i], central_difference(false, i),
                  1e-6 * std::max(1.0, std::abs(at.weight_gradient[i])))
          << "weight " << i << ", gap " << minimum_gap;
    }
  }
}


// ---- animation paths ---------------------------------------------------------------------------

// Keys of a path: times in [0, 1] and positions, as a PositionInterpolator holds them.
struct Keys {
  std::vector<double> times;
  std::vector<Eigen::Vector3d> positions;
};

// The samples a path fit must meet: every key, and halfway between keys the keys' linear
// interpolation (what the original interpolator plays there).
CurveSamples keys_and_halfway_points(const Keys& keys) {
  CurveSamples samples;
  for (size_t i = 0; i < keys.times.size(); ++i) {
    if (i > 0) {
      samples.parameters.push_back(0.5 * (keys.times[i - 1] + keys.times[i]));
      samples.points.push_back(0.5 * (keys.positions[i - 1] + keys.positions[i]));
    }
    samples.parameters.push_back(keys.times[i]);
    samples.points.push_back(keys.positions[i]);
  }
  return samples;
}

// The largest distance from the curve to the keys and to the halfway points, measured here again.
double error_at_keys_and_halfway(const NurbsCurve& curve, const Keys& keys) {
  double error = 0;
  for (size_t i = 0; i < keys.times.size(); ++i) {
    error = std::max(error, (curve_point(curve, keys.times[i]) - keys.positions[i]).norm());
    if (i == 0) continue;
    const double t = 0.5 * (keys.times[i - 1] + keys.times[i]);
    const Eigen::Vector3d halfway = 0.5 * (keys.positions[i - 1] + keys.positions[i]);
    error = std::max(error, (curve_point(curve, t) - halfway).norm());
  }
  return error;
}

constexpr double kTwoPi = 2 * std::numbers::pi;

// A circle of radius 1 at `count` evenly spaced keys.
Keys circle_keys(int count = 1000) {
  Keys keys;
  for (int i = 0; i < count; ++i) {
    const double t = i / (count - 1.0);
    keys.times.push_back(t);
    keys.positions.emplace_back(std::cos(kTwoPi * t), std::sin(kTwoPi * t), 0.0);
  }
  return keys;
}

// Three turns of a helix of radius 1 and pitch 0.5 at 600 evenly spaced keys.
Keys helix_keys() {
  Keys keys;
  for (int i = 0; i < 600; ++i) {
    const double t = i / 599.0;
    keys.times.push_back(t);
    keys.positions.emplace_back(std::cos(3 * kTwoPi * t), std::sin(3 * kTwoPi * t), 1.5 * t);
  }
  return keys;
}

// A figure-eight (Gerono's lemniscate, width 2) whose 400 keys are unevenly spaced in time, and whose
// motion speeds up towards the end: the places that need knots are not where the keys crowd.
Keys figure_eight_keys() {
  Keys keys;
  for (int i = 0; i < 400; ++i) {
    const double s = i / 399.0;
    const double t = s + 0.04 * std::sin(3 * kTwoPi * s);  // increasing: 0.04 * 3 * 2 pi < 1
    const double angle = kTwoPi * std::pow(t, 1.5);
    keys.times.push_back(t);
    keys.positions.emplace_back(std::sin(angle), std::sin(angle) * std::cos(angle), 0.0);
  }
  return keys;
}

// A recorded-style path: a wandering walk (sums of slow sines, of size about 2) at 500 keys, each
// moved by noise of length up to `noise` in a random direction (fixed seed).
Keys recorded_keys(double noise) {
  Keys keys;
  std::mt19937 random(20261127);
  auto uniform = [&] { return random() / 4294967296.0; };
  for (int i = 0; i < 500; ++i) {
    const double t = i / 499.0;
    const Eigen::Vector3d smooth(std::sin(kTwoPi * 1.3 * t) + 0.3 * std::sin(kTwoPi * 4.1 * t + 1),
                                 std::cos(kTwoPi * 0.9 * t) + 0.25 * std::sin(kTwoPi * 5.3 * t),
                                 0.4 * std::sin(kTwoPi * 2.2 * t + 0.5));
    const double z = 2 * uniform() - 1, phi = kTwoPi * uniform();
    const Eigen::Vector3d direction(std::sqrt(1 - z * z) * std::cos(phi), std::sqrt(1 - z * z) * std::sin(phi), z);
    keys.times.push_back(t);
    keys.positions.push_back(smooth + noise * uniform() * direction);
  }
  return keys;
}

void expect_clamped_and_feasible(const CurveFit& fit, const CurveFitOptions& options) {
  const NurbsCurve& curve = fit.curve;
  EXPECT_EQ(curve.dimension, 3);
  EXPECT_EQ(fit_constraint_fault(curve, options.minimum_knot_gap), "");
  for (int i = 0; i < curve.order; ++i) {
    EXPECT_EQ(curve.knots[i], 0.0);
    EXPECT_EQ(curve.knots[curve.count() + i], 1.0);
  }
  EXPECT_EQ(curve.domain_start(), 0.0);
  EXPECT_EQ(curve.domain_end(), 1.0);
  for (double w : curve.weights) EXPECT_GT(w, 0.0);
  EXPECT_EQ(knot_vector_fault(curve.knots, curve.order, curve.count()), "");
}

struct PathCase {
  const char* name;
  Keys keys;
  double deviation;
  bool smooth;
};

std::vector<PathCase> path_cases() {
  const double recorded_deviation = 0.01;
  return {{"circle", circle_keys(), 1e-3, true},
          {"helix", helix_keys(), 1e-3, true},
          {"figure-eight", figure_eight_keys(), 1e-3, true},
          {"recorded", recorded_keys(recorded_deviation / 10), recorded_deviation, false}};
}

TEST(FitCurve, PathsWithinTheDeviationAtKeysAndHalfway) {
  const CurveFitOptions options;
  CurveFitOptions fixed;  // for the print only: what the refinement needs without knot or weight optimisation
  fixed.optimise_knots = false;
  fixed.optimise_weights = false;
  for (const PathCase& path : path_cases()) {
    const CurveFit fit = fit_curve_within(keys_and_halfway_points(path.keys), path.deviation, options);
    const CurveFit plain = fit_curve_within(keys_and_halfway_points(path.keys), path.deviation, fixed);
    const double error = error_at_keys_and_halfway(fit.curve, path.keys);
    std::printf("%-13s %4zu keys -> %3d control points (%3d at fixed knots), max error %.3g (D %.3g), %d refinements, "
                "%d CG iterations\n",
                path.name, path.keys.times.size(), fit.curve.count(), plain.curve.count(), error, path.deviation,
                fit.refinements, fit.iterations);
    EXPECT_LE(error, path.deviation) << path.name;
    EXPECT_NEAR(error, fit.max_error, 1e-12) << path.name;
    if (path.smooth) {
      EXPECT_LE(10 * fit.curve.count(), static_cast<int>(path.keys.times.size())) << path.name;
    }
    expect_clamped_and_feasible(fit, options);
  }
}

// At equal control-point counts, the optimised knots (with and without weights) fit better than least
// squares at fixed uniform knots and at fixed averaged knots (Piegl & Tiller 9.69): the rms error, which
// the fit minimises, always; the max error is printed beside it.
TEST(FitCurve, OptimisedKnotsBeatUniformAndAveragedKnots) {
  for (const PathCase& path : path_cases()) {
    const CurveSamples samples = keys_and_halfway_points(path.keys);
    const int count = path.smooth ? 12 : 20;
    CurveFitOptions optimised;
    CurveFitOptions knots_only;
    knots_only.optimise_weights = false;
    CurveFitOptions averaged = knots_only;
    averaged.optimise_knots = false;
    CurveFitOptions uniform = averaged;
    uniform.initial_knots = InitialKnots::uniform;
    const CurveFit best = fit_curve(samples, count, optimised);
    const CurveFit polynomial = fit_curve(samples, count, knots_only);
    const CurveFit at_averaged = fit_curve(samples, count, averaged);
    const CurveFit at_uniform = fit_curve(samples, count, uniform);
    std::printf("%-13s %d control points, rms error ratios: knots+weights/averaged %.3f, /uniform %.3f, "
                "knots only/averaged %.3f, /uniform %.3f; max error ratios %.3f %.3f %.3f %.3f\n",
                path.name, count, best.rms_error / at_averaged.rms_error, best.rms_error / at_uniform.rms_error,
                polynomial.rms_error / at_averaged.rms_error, polynomial.rms_error / at_uniform.rms_error,
                best.max_error / at_averaged.max_error, best.max_error / at_uniform.max_error,
                polynomial.max_error / at_averaged.max_error, polynomial.max_error / at_uniform.max_error);
    for (const CurveFit* fit : {&best, &polynomial}) {
      EXPECT_LT(fit->rms_error / at_averaged.rms_error, 1.0) << path.name;
      EXPECT_LT(fit->rms_error / at_uniform.rms_error, 1.0) << path.name;
    }
    expect_clamped_and_feasible(best, optimised);
    expect_clamped_and_feasible(polynomial, knots_only);
    EXPECT_TRUE(polynomial.curve.weights.empty());
    EXPECT_TRUE(at_averaged.curve.weights.empty());
    EXPECT_EQ(at_averaged.iterations, 0);
    EXPECT_EQ(at_uniform.curve.knots, clamped_uniform_knots(4, count));
  }
}

// Orders 2 and 3 (what a path of two or three keys gets): the fits are within tolerance at the keys
// and halfway points, with clamped knots.
TEST(FitCurve, LowOrdersFitToo) {
  Keys keys;
  keys.times = {0.0, 0.3, 1.0};
  keys.positions = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 2, 0), Eigen::Vector3d(3, 1, 1)};
  for (const int order : {2, 3}) {
    CurveFitOptions options;
    options.order = order;
    options.optimise_weights = false;
    const CurveFit fit = fit_curve_within(keys_and_halfway_points(keys), 1e-3, options);
    EXPECT_LE(error_at_keys_and_halfway(fit.curve, keys), 1e-3) << "order " << order;
    EXPECT_EQ(fit.curve.order, order);
    expect_clamped_and_feasible(fit, options);
  }
  CurveFitOptions options;
  options.order = 3;
  const Keys circle = circle_keys(300);
  const CurveFit fit = fit_curve_within(keys_and_halfway_points(circle), 1e-3, options);
  EXPECT_LE(error_at_keys_and_halfway(fit.curve, circle), 1e-3);
  EXPECT_LE(10 * fit.curve.count(), 300);
}

TEST(FitCurve, RefusesWhatItCannotFit) {
  CurveSamples samples;
  for (int j = 0; j < 30; ++j) {
    samples.parameters.push_back(j / 29.0);
    samples.points.emplace_back(std::sin(7.3 * j), std::cos(11.1 * j), j % 3);  // no smooth curve through these
  }
  // Two points 1 apart at one parameter: no curve meets both within less than 0.5.
  samples.parameters.insert(samples.parameters.begin() + 11, samples.parameters[10]);
  samples.points.insert(samples.points.begin() + 11, samples.points[10] + Eigen::Vector3d(1, 0, 0));
  try {
    fit_curve(samples, 31, {});
    FAIL() << "31 control points for 30 samples";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "fit_curve: 31 control points need at least as many distinct sample parameters (30)");
  }
  try {
    fit_curve_within(samples, 1e-3, {});
    FAIL() << "two points at one parameter within 1e-3";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("fit_curve_within: the data cannot be met within 0.001: the refinement would need "),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("more than the 30 distinct sample parameters"), std::string::npos) << e.what();
  }
  CurveSamples backwards = samples;
  std::swap(backwards.parameters[3], backwards.parameters[4]);  // 3/29 after 4/29
  try {
    fit_curve(backwards, 8, {});
    FAIL() << "decreasing parameters";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "fit_curve: parameter 4 decreases");
  }
}

// Where the data are met by few control points, fit_curve_within stops early: a cubic polynomial arc
// sampled at 200 keys is met with the starting five control points, and no refinement.
TEST(FitCurve, StopsWithoutRefinementWhenTheStartMeetsTheTolerance) {
  CurveSamples samples;
  for (int j = 0; j < 200; ++j) {
    const double t = j / 199.0;
    samples.parameters.push_back(t);
    samples.points.emplace_back(t, t * t * t - t, 2 * t * t);
  }
  const CurveFit fit = fit_curve_within(samples, 1e-6, {});
  EXPECT_EQ(fit.refinements, 0);
  EXPECT_EQ(fit.curve.count(), 5);
  EXPECT_LE(fit.max_error, 1e-6);
}

}  // namespace
}  // namespace cadnurbs
