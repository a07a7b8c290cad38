// bench_fit_curve: fit_curve on the 1,000-key circle of the tests (keys and the halfway points between
// them, 1,999 samples), side by side in one run with Eigen's plain least squares (column-pivoting
// Householder QR of the collocation matrix) at fixed averaged knots with the same control-point count.
// Prints, for each, the time (the fastest of `rounds` runs), the CG iterations, and the max and rms
// errors at the samples; then the ratios. Also the refinement with fixed knots and no weights, for the
// control-point count plain least squares needs for the same deviation. Last, one run each on a
// 10,000-key wandering path the way fit-path fits it (weights off), optimised against fixed knots.
// Then the same comparison for fit_surface on two 100 x 100 grids: a bicubic B-spline surface of 16 x 12
// control points with crowded knots, and a height field with a sharp ridge (in no spline
// space), Eigen's plain least squares there being QR of the whole tensor-product collocation matrix.
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

#include "analysis/fitting/fit_curve.hpp"
#include "analysis/fitting/fit_surface.hpp"
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

// One fitter's line against Eigen's: time, max and rms error.
struct Figures {
  double seconds, max, rms;
};

// The ratios to Eigen's plain least squares of the refinement, the fit at its count and the fit at fixed knots.
void print_ratios(const char* fit, const Figures& within, const Figures& optimised, const Figures& fixed,
                  const Figures& eigen) {
  std::printf("ratios against Eigen: time within %.1f, %s %.1f, fixed %.3g; max error within %.3g, %s %.3g, fixed %.3g; "
              "rms error within %.3g, %s %.3g, fixed %.3g\n",
              within.seconds / eigen.seconds, fit, optimised.seconds / eigen.seconds, fixed.seconds / eigen.seconds,
              within.max / eigen.max, fit, optimised.max / eigen.max, fixed.max / eigen.max, within.rms / eigen.rms, fit,
              optimised.rms / eigen.rms, fixed.rms / eigen.rms);
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

// Plain least squares for a grid: the tensor-product collocation matrix (one row per grid point, one
// column per control point), solved by column-pivoting Householder QR.
NurbsSurface eigen_surface_least_squares(const GridSamples& grid, const NurbsSurface& knots_from) {
  NurbsSurface surface = knots_from;
  const int m = static_cast<int>(grid.u.size()), n = static_cast<int>(grid.v.size());
  const int cu = surface.u_count, cv = surface.v_count, ku = surface.u_order, kv = surface.v_order;
  Eigen::MatrixXd collocation = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(m) * n, cu * cv);
  Eigen::MatrixXd right(static_cast<Eigen::Index>(m) * n, 3);
  for (int j = 0; j < n; ++j) {
    const int v_span = find_knot_span(surface.v_knots, kv, cv, grid.v[j]);
    const auto v_basis = basis_function_derivatives(surface.v_knots, kv, v_span, grid.v[j], 0);
    for (int i = 0; i < m; ++i) {
      const int u_span = find_knot_span(surface.u_knots, ku, cu, grid.u[i]);
      const auto u_basis = basis_function_derivatives(surface.u_knots, ku, u_span, grid.u[i], 0);
      for (int s = 0; s < kv; ++s) {
        for (int r = 0; r < ku; ++r) {
          collocation(i + j * m, (u_span - ku + 1 + r) + cu * (v_span - kv + 1 + s)) = u_basis[0][r] * v_basis[0][s];
        }
      }
      right.row(i + j * m) = grid.points[i + j * m].transpose();
    }
  }
  const Eigen::MatrixXd solution = collocation.colPivHouseholderQr().solve(right);
  for (int k = 0; k < cu * cv; ++k) surface.points[k] = solution.row(k).transpose();
  return surface;
}

Errors errors_of(const NurbsSurface& surface, const GridSamples& grid) {
  Errors e;
  const size_t m = grid.u.size();
  for (size_t j = 0; j < grid.v.size(); ++j) {
    for (size_t i = 0; i < m; ++i) {
      const double d = (surface_point(surface, grid.u[i], grid.v[j]) - grid.points[i + j * m]).norm();
      e.max = std::max(e.max, d);
      e.rms += d * d;
    }
  }
  e.rms = std::sqrt(e.rms / grid.points.size());
  return e;
}

GridSamples grid_of(const std::function<Eigen::Vector3d(double, double)>& at) {
  GridSamples grid;
  for (int i = 0; i < 100; ++i) grid.u.push_back(i / 99.0), grid.v.push_back(i / 99.0);
  for (int j = 0; j < 100; ++j) {
    for (int i = 0; i < 100; ++i) grid.points.push_back(at(grid.u[i], grid.v[j]));
  }
  return grid;
}

// fit_surface_within, fit_surface at its count, the same at fixed averaged knots, the refinement at fixed
// knots, and Eigen's QR at the fixed averaged knots: one table per grid.
void bench_surface(const char* name, const GridSamples& grid, double deviation, int rounds) {
  const SurfaceFitOptions options;
  SurfaceFitOptions fixed = options;
  fixed.optimise_knots = false;
  SurfaceFit within, optimised, at_averaged, within_fixed;
  const double within_seconds = fastest_seconds(rounds, [&] { within = fit_surface_within(grid, deviation, options); });
  const int cu = within.surface.u_count, cv = within.surface.v_count;
  const double optimised_seconds = fastest_seconds(rounds, [&] { optimised = fit_surface(grid, cu, cv, options); });
  const double fixed_seconds = fastest_seconds(rounds, [&] { at_averaged = fit_surface(grid, cu, cv, fixed); });
  const double within_fixed_seconds =
      fastest_seconds(rounds, [&] { within_fixed = fit_surface_within(grid, deviation, fixed); });
  NurbsSurface plain;
  const double eigen_seconds =
      fastest_seconds(rounds, [&] { plain = eigen_surface_least_squares(grid, at_averaged.surface); });
  const Errors eigen_errors = errors_of(plain, grid);

  std::printf("\n%s, 100 x 100 grid, D = %g, fastest of %d runs\n", name, deviation, rounds);
  std::printf("%-46s %9s %8s %6s %11s %11s\n", "", "seconds", "points", "CG it", "max error", "rms error");
  auto row = [](const char* what, double seconds, const SurfaceFit& fit) {
    std::printf("%-46s %9.4f %3d x %-3d %6d %11.3e %11.3e\n", what, seconds, fit.surface.u_count, fit.surface.v_count,
                fit.iterations, fit.max_error, fit.rms_error);
  };
  row("fit_surface_within (refinement + CG)", within_seconds, within);
  row("fit_surface, same counts (averaged start + CG)", optimised_seconds, optimised);
  row("fit_surface, fixed averaged knots", fixed_seconds, at_averaged);
  row("fit_surface_within, fixed knots", within_fixed_seconds, within_fixed);
  std::printf("%-46s %9.4f %3d x %-3d %6s %11.3e %11.3e\n", "Eigen QR least squares, fixed averaged knots",
              eigen_seconds, plain.u_count, plain.v_count, "-", eigen_errors.max, eigen_errors.rms);
  print_ratios("fit_surface", {within_seconds, within.max_error, within.rms_error},
               {optimised_seconds, optimised.max_error, optimised.rms_error},
               {fixed_seconds, at_averaged.max_error, at_averaged.rms_error}, {eigen_seconds, eigen_errors.max, eigen_errors.rms});
}

// A denser bicubic net than the tests': 16 x 12 control points, interior knots crowded towards u = 0
// and v = 1 (squares and square roots of uniform ones), heights from two waves.
NurbsSurface dense_bicubic() {
  NurbsSurface surface;
  surface.u_order = surface.v_order = 4;
  surface.u_count = 16;
  surface.v_count = 12;
  surface.u_knots = clamped_uniform_knots(4, 16);
  surface.v_knots = clamped_uniform_knots(4, 12);
  for (double& u : surface.u_knots) u = u * u;
  for (double& v : surface.v_knots) v = std::sqrt(v);
  for (int j = 0; j < surface.v_count; ++j) {
    for (int i = 0; i < surface.u_count; ++i) {
      surface.points.emplace_back(i / 15.0, j / 11.0, 0.2 * std::sin(0.9 * i) * std::cos(0.6 * j) + 0.05 * std::sin(2.3 * i * j));
    }
  }
  return surface;
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
  print_ratios("fit_curve", {within_seconds, within.max_error, within.rms_error},
               {optimised_seconds, optimised.max_error, optimised.rms_error},
               {fixed_seconds, at_averaged.max_error, at_averaged.rms_error}, {eigen_seconds, eigen_errors.max, eigen_errors.rms});

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

  const NurbsSurface bicubic = dense_bicubic();
  bench_surface("bicubic B-spline surface, 16 x 12 control points, crowded knots",
                grid_of([&](double u, double v) { return surface_point(bicubic, u, v); }), 1e-3, rounds);
  bench_surface("ridge height field z = 0.5 sqrt((u - 0.37)^2 + 0.005^2) + 0.05 sin(pi v)", grid_of([](double u, double v) {
                  const double d = u - 0.37;
                  return Eigen::Vector3d(u, v, 0.5 * std::sqrt(d * d + 0.005 * 0.005) + 0.05 * std::sin(std::numbers::pi * v));
                }),
                1e-3, rounds);
  return 0;
}
