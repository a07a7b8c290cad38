// bench_fit_curve: fit_curve on the 1,000-key circle of the tests (keys and the halfway points between
// them, 1,999 samples), side by side in one run with Eigen's plain least squares (column-pivoting
// Householder QR of the collocation matrix) at fixed averaged knots with the same control-point count.
// Prints, for each, the time (the fastest of `rounds` runs), the CG iterations, and the max and rms
// errors at the samples; then the ratios. Also the refinement with fixed knots and no weights, for the
// control-point count plain least squares needs for the same deviation. Last, one run each on a
// 10,000-key wandering path the way fit-path fits it (weights off), optimised against fixed knots.
//
//   bench_fit_curve [rounds]      (default 5)
#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <numbers>
#include <random>

#include "analysis/fit_curve.hpp"
#include "core/knot_vector.hpp"

namespace {

using namespace cadnurbs;
constexpr double kDeviation = 1e-3;  // the circle has radius 1

CurveSamples circle_samples() {
  CurveSamples samples;
  const int keys = 1000;
  for (int i = 0; i < 2 * keys - 1; ++i) {
    const double t = i / (2.0 * keys - 2);
    // Keys on the circle; halfway points on the chord between two keys (what the original plays there).
    auto on_circle = [](double s) {
      return Eigen::Vector3d(std::cos(2 * std::numbers::pi * s), std::sin(2 * std::numbers::pi * s), 0.0);
    };
    const Eigen::Vector3d point =
        i % 2 == 0 ? on_circle(t) : 0.5 * (on_circle((i - 1) / (2.0 * keys - 2)) + on_circle((i + 1) / (2.0 * keys - 2)));
    samples.parameters.push_back(t);
    samples.points.push_back(point);
  }
  return samples;
}

// A wandering path of `keys` keys (sums of sines, size about 2) with noise up to 0.001 (fixed seed), keys
// and halfway points: what a long recorded animation gives fit-path.
CurveSamples wandering_samples(int keys) {
  CurveSamples samples;
  std::mt19937 random(5);
  auto uniform = [&] { return random() / 4294967296.0; };
  const double two_pi = 2 * std::numbers::pi;
  for (int i = 0; i < 2 * keys - 1; ++i) {
    const double t = i / (2.0 * keys - 2);
    const Eigen::Vector3d smooth(std::sin(two_pi * 5.3 * t) + 0.3 * std::sin(two_pi * 17 * t), std::cos(two_pi * 3.9 * t),
                                 0.4 * std::sin(two_pi * 8 * t));
    samples.parameters.push_back(t);
    samples.points.push_back(smooth + 0.001 * Eigen::Vector3d(uniform(), uniform(), uniform()));
  }
  return samples;
}

double fastest_seconds(int rounds, const std::function<void()>& run) {
  double best = 1e300;
  for (int r = 0; r < rounds; ++r) {
    const auto start = std::chrono::steady_clock::now();
    run();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

struct Errors {
  double max = 0;
  double rms = 0;
};

Errors errors_of(const NurbsCurve& curve, const CurveSamples& samples) {
  Errors e;
  for (size_t j = 0; j < samples.parameters.size(); ++j) {
    const double d = (curve_point(curve, samples.parameters[j]) - samples.points[j]).norm();
    e.max = std::max(e.max, d);
    e.rms += d * d;
  }
  e.rms = std::sqrt(e.rms / samples.parameters.size());
  return e;
}

// Plain least squares with Eigen: the collocation matrix of the B-spline basis at the sample parameters
// (core's basis functions), solved by column-pivoting Householder QR for the control points.
NurbsCurve eigen_least_squares(const CurveSamples& samples, const std::vector<double>& knots, int order) {
  const int count = static_cast<int>(knots.size()) - order;
  const int m = static_cast<int>(samples.parameters.size());
  Eigen::MatrixXd collocation = Eigen::MatrixXd::Zero(m, count);
  Eigen::MatrixXd right(m, 3);
  for (int j = 0; j < m; ++j) {
    const double t = samples.parameters[j];
    const int span = find_knot_span(knots, order, count, t);
    const auto basis = basis_function_derivatives(knots, order, span, t, 0);
    for (int i = 0; i < order; ++i) collocation(j, span - order + 1 + i) = basis[0][i];
    right.row(j) = samples.points[j].transpose();
  }
  const Eigen::MatrixXd solution = collocation.colPivHouseholderQr().solve(right);
  NurbsCurve curve;
  curve.order = order;
  curve.knots = knots;
  for (int i = 0; i < count; ++i) curve.points.push_back(solution.row(i).transpose());
  return curve;
}

}  // namespace

int main(int argc, char** argv) {
  const int rounds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  const CurveSamples samples = circle_samples();
  const CurveFitOptions options;

  CurveFit within;
  const double within_seconds = fastest_seconds(rounds, [&] { within = fit_curve_within(samples, kDeviation, options); });
  const int count = within.curve.count();

  CurveFit optimised;
  const double optimised_seconds = fastest_seconds(rounds, [&] { optimised = fit_curve(samples, count, options); });

  CurveFitOptions fixed = options;
  fixed.optimise_knots = false;
  fixed.optimise_weights = false;
  CurveFit at_averaged;
  const double fixed_seconds = fastest_seconds(rounds, [&] { at_averaged = fit_curve(samples, count, fixed); });

  CurveFit within_fixed;
  const double within_fixed_seconds =
      fastest_seconds(rounds, [&] { within_fixed = fit_curve_within(samples, kDeviation, fixed); });

  NurbsCurve plain;
  const double eigen_seconds =
      fastest_seconds(rounds, [&] { plain = eigen_least_squares(samples, at_averaged.curve.knots, options.order); });
  const Errors eigen_errors = errors_of(plain, samples);

  std::printf("circle, 1000 keys + 999 halfway points, D = %g (radius 1), fastest of %d runs\n", kDeviation, rounds);
  std::printf("%-46s %9s %6s %6s %11s %11s\n", "", "seconds", "points", "CG it", "max error", "rms error");
  std::printf("%-46s %9.4f %6d %6d %11.3e %11.3e\n", "fit_curve_within (refinement + CG)", within_seconds,
              within.curve.count(), within.iterations, within.max_error, within.rms_error);
  std::printf("%-46s %9.4f %6d %6d %11.3e %11.3e\n", "fit_curve, same count (averaged start + CG)", optimised_seconds,
              optimised.curve.count(), optimised.iterations, optimised.max_error, optimised.rms_error);
  std::printf("%-46s %9.4f %6d %6d %11.3e %11.3e\n", "fit_curve, fixed averaged knots, polynomial", fixed_seconds,
              at_averaged.curve.count(), at_averaged.iterations, at_averaged.max_error, at_averaged.rms_error);
  std::printf("%-46s %9.4f %6d %6d %11.3e %11.3e\n", "fit_curve_within, fixed knots, polynomial", within_fixed_seconds,
              within_fixed.curve.count(), within_fixed.iterations, within_fixed.max_error, within_fixed.rms_error);
  std::printf("%-46s %9.4f %6d %6s %11.3e %11.3e\n", "Eigen QR least squares, fixed averaged knots", eigen_seconds,
              plain.count(), "-", eigen_errors.max, eigen_errors.rms);
  std::printf("ratios against Eigen: time within %.1f, fit_curve %.1f, fixed %.2f; max error within %.3f, fit_curve %.3f, "
              "fixed %.3f; rms error within %.3f, fit_curve %.3f, fixed %.3f\n",
              within_seconds / eigen_seconds, optimised_seconds / eigen_seconds, fixed_seconds / eigen_seconds,
              within.max_error / eigen_errors.max, optimised.max_error / eigen_errors.max,
              at_averaged.max_error / eigen_errors.max, within.rms_error / eigen_errors.rms,
              optimised.rms_error / eigen_errors.rms, at_averaged.rms_error / eigen_errors.rms);

  // fit-path's use on a long recording: knots optimised, weights off, D = 0.01; one run each.
  const CurveSamples long_path = wandering_samples(10000);
  CurveFitOptions knots_only = options;
  knots_only.optimise_weights = false;
  CurveFit long_optimised, long_fixed;
  const double long_optimised_seconds =
      fastest_seconds(1, [&] { long_optimised = fit_curve_within(long_path, 0.01, knots_only); });
  const double long_fixed_seconds = fastest_seconds(1, [&] { long_fixed = fit_curve_within(long_path, 0.01, fixed); });
  std::printf("wandering path, 10000 keys, D = 0.01, weights off: knots optimised %d control points, %d CG iterations, "
              "%d refinements, %.2f s; fixed knots %d control points, %.3f s (time ratio %.0f)\n",
              long_optimised.curve.count(), long_optimised.iterations, long_optimised.refinements, long_optimised_seconds,
              long_fixed.curve.count(), long_fixed_seconds, long_optimised_seconds / long_fixed_seconds);
  return 0;
}
