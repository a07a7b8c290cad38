// fit_surface and its energy: the separated solve against a plain least-squares solve, the knot
// gradient against finite differences, a dense bicubic surface refitted within D, knots gathering at a
// ridge, and the refusals.
#include "analysis/fitting/fit_surface.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>

#include "analysis/fitting/surface_fit_energy.hpp"
#include "core/knot_vector.hpp"

namespace cadnurbs {
namespace {

GridSamples sample_grid(int m, int n, const std::function<Eigen::Vector3d(double, double)>& at) {
  GridSamples grid;
  for (int i = 0; i < m; ++i) grid.u.push_back(i / (m - 1.0));
  for (int j = 0; j < n; ++j) grid.v.push_back(j / (n - 1.0));
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < m; ++i) grid.points.push_back(at(grid.u[i], grid.v[j]));
  }
  return grid;
}

Eigen::Vector3d wave(double u, double v) {
  return {u + 0.1 * std::sin(3 * v), v, 0.3 * std::sin(2 * std::numbers::pi * u) * std::cos(1.5 * v) + 0.2 * u * v};
}

// A bicubic surface of 8 x 7 control points with uneven interior knots and a wavy net: the shape to refit.
NurbsSurface wavy_bicubic() {
  NurbsSurface surface;
  surface.u_order = surface.v_order = 4;
  surface.u_count = 8;
  surface.v_count = 7;
  surface.u_knots = {0, 0, 0, 0, 0.15, 0.3, 0.5, 0.8, 1, 1, 1, 1};
  surface.v_knots = {0, 0, 0, 0, 0.25, 0.4, 0.7, 1, 1, 1, 1};
  for (int j = 0; j < surface.v_count; ++j) {
    for (int i = 0; i < surface.u_count; ++i) {
      surface.points.emplace_back(i / 7.0, j / 6.0, 0.25 * std::sin(1.3 * i + 0.7 * j) + 0.1 * ((i * j) % 3));
    }
  }
  return surface;
}

TEST(SurfaceFitEnergy, SolvesTheSameControlPointsAsPlainLeastSquares) {
  const GridSamples grid = sample_grid(30, 25, wave);
  const std::vector<double> u_knots = {0, 0, 0, 0, 0.2, 0.35, 0.6, 1, 1, 1, 1};  // 7 control points
  const std::vector<double> v_knots = {0, 0, 0, 0.3, 0.5, 0.9, 1, 1, 1};         // order 3, 6 control points
  const SurfaceFitEvaluation e = evaluate_surface_fit_energy(grid, 4, 3, u_knots, v_knots, {}, false);
  ASSERT_EQ(e.control_points.size(), 42u);
  // The whole tensor-product system at once: one row per grid point, one column per control point.
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(30 * 25, 42);
  Eigen::MatrixXd b(30 * 25, 3);
  for (int j = 0; j < 25; ++j) {
    for (int i = 0; i < 30; ++i) {
      const auto nu = basis_function_derivatives(u_knots, 4, find_knot_span(u_knots, 4, 7, grid.u[i]), grid.u[i], 0);
      const auto nv = basis_function_derivatives(v_knots, 3, find_knot_span(v_knots, 3, 6, grid.v[j]), grid.v[j], 0);
      const int su = find_knot_span(u_knots, 4, 7, grid.u[i]) - 3, sv = find_knot_span(v_knots, 3, 6, grid.v[j]) - 2;
      for (int r = 0; r < 4; ++r) {
        for (int s = 0; s < 3; ++s) a(i + 30 * j, (su + r) + 7 * (sv + s)) = nu[0][r] * nv[0][s];
      }
      b.row(i + 30 * j) = grid.points[i + 30 * j].transpose();
    }
  }
  const Eigen::MatrixXd plain = a.colPivHouseholderQr().solve(b);
  double largest = 0;
  for (int k = 0; k < 42; ++k) largest = std::max(largest, (plain.row(k).transpose() - e.control_points[k]).norm());
  EXPECT_LT(largest, 1e-9);
  EXPECT_NEAR(e.data_energy, (a * plain - b).squaredNorm() / (30 * 25), 1e-12);
}

TEST(SurfaceFitEnergy, KnotGradientMatchesFiniteDifferences) {
  const GridSamples grid = sample_grid(30, 25, wave);
  const std::vector<double> u_knots = {0, 0, 0, 0, 0.2, 0.35, 0.6, 1, 1, 1, 1};
  const std::vector<double> v_knots = {0, 0, 0, 0.3, 0.5, 0.9, 1, 1, 1};
  SurfaceFitEnergyTerms terms;
  terms.fairness = 1e-4;  // large enough that the bending terms weigh in the gradient
  terms.knot_spread = 1e-3;
  terms.minimum_gap = 1e-3;
  terms.scale = 0.01;
  const SurfaceFitEvaluation e = evaluate_surface_fit_energy(grid, 4, 3, u_knots, v_knots, terms, true);
  ASSERT_TRUE(std::isfinite(e.energy));
  EXPECT_GT(e.fairness_energy, 1e-3 * e.energy);
  const double h = 1e-6;
  for (int direction = 0; direction < 2; ++direction) {
    const std::vector<double>& knots = direction == 0 ? u_knots : v_knots;
    const int order = direction == 0 ? 4 : 3;
    for (size_t i = order; i + order < knots.size(); ++i) {
      std::vector<double> plus = knots, minus = knots;
      plus[i] += h;
      minus[i] -= h;
      auto energy = [&](const std::vector<double>& k) {
        return direction == 0 ? evaluate_surface_fit_energy(grid, 4, 3, k, v_knots, terms, false).energy
                              : evaluate_surface_fit_energy(grid, 4, 3, u_knots, k, terms, false).energy;
      };
      const double numeric = (energy(plus) - energy(minus)) / (2 * h);
      const double analytic = direction == 0 ? e.u_knot_gradient[i] : e.v_knot_gradient[i];
      EXPECT_NEAR(analytic, numeric, 1e-6 * std::abs(numeric) + 1e-9) << "direction " << direction << " knot " << i;
    }
  }
}

// The check: a dense B-spline surface sampled on a 100 x 100 grid is refitted within D with at
// most a tenth of the samples as control points; within D on the grid and between it (cell centres,
// against the original surface).
TEST(FitSurface, RefitsASampledBicubicSurfaceWithinD) {
  const NurbsSurface original = wavy_bicubic();
  const GridSamples grid = sample_grid(100, 100, [&](double u, double v) { return surface_point(original, u, v); });
  const double tolerance = 1e-3;  // the surface spans about 1 x 1 x 0.6
  const SurfaceFit fit = fit_surface_within(grid, tolerance, SurfaceFitOptions{});
  const int control_points = fit.surface.u_count * fit.surface.v_count;
  std::printf("bicubic 100x100: %d x %d control points, max error %.3g, %d CG iterations, %d refinements\n",
              fit.surface.u_count, fit.surface.v_count, fit.max_error, fit.iterations, fit.refinements);
  EXPECT_LE(control_points, 1000);
  EXPECT_NO_THROW(validate(fit.surface, "fit"));
  EXPECT_EQ(fit.surface.u_knots.front(), 0.0);
  EXPECT_EQ(fit.surface.u_knots.back(), 1.0);
  EXPECT_EQ(fit.surface.v_knots.front(), 0.0);
  EXPECT_EQ(fit.surface.v_knots.back(), 1.0);
  EXPECT_LE(fit.max_error, tolerance);
  double on_grid = 0, between = 0;
  for (int j = 0; j < 100; ++j) {
    for (int i = 0; i < 100; ++i) {
      const double u = grid.u[i], v = grid.v[j];
      on_grid = std::max(on_grid, (surface_point(fit.surface, u, v) - surface_point(original, u, v)).norm());
      if (i == 99 || j == 99) continue;
      const double uc = 0.5 * (u + grid.u[i + 1]), vc = 0.5 * (v + grid.v[j + 1]);
      between = std::max(between, (surface_point(fit.surface, uc, vc) - surface_point(original, uc, vc)).norm());
    }
  }
  EXPECT_LE(on_grid, tolerance);
  EXPECT_LE(between, tolerance);
  EXPECT_NEAR(on_grid, fit.max_error, 1e-12);
}

// A height field with a sharp ridge along u = 0.37 (|u - 0.37| smoothed over a band of 0.005), gently
// bent in v.
GridSamples ridge_grid() {
  return sample_grid(100, 30, [](double u, double v) {
    const double d = u - 0.37;
    return Eigen::Vector3d(u, v, 0.5 * std::sqrt(d * d + 0.005 * 0.005) + 0.05 * std::sin(std::numbers::pi * v));
  });
}

// The check: the knots gather at the ridge, more u knots in its tenth of the domain than in any
// other tenth.
TEST(FitSurface, ConcentratesKnotsAtARidge) {
  const SurfaceFit fit = fit_surface_within(ridge_grid(), 1e-3, SurfaceFitOptions{});
  EXPECT_LE(fit.max_error, 1e-3);
  const NurbsSurface& s = fit.surface;
  std::array<int, 10> per_tenth{};
  for (int i = s.u_order; i < s.u_count; ++i) ++per_tenth[std::min(9, static_cast<int>(s.u_knots[i] * 10))];
  std::printf("ridge: %d x %d control points, u knots per tenth:", s.u_count, s.v_count);
  for (int count : per_tenth) std::printf(" %d", count);
  std::printf("\n");
  for (int tenth = 0; tenth < 10; ++tenth) {
    if (tenth != 3) {
      EXPECT_GT(per_tenth[3], per_tenth[tenth]) << "tenth " << tenth;
    }
  }
  EXPECT_EQ(fit_constraint_fault(NurbsCurve{3, s.u_order, s.u_knots, std::vector<Eigen::Vector3d>(s.u_count), {}}, 1e-4), "");
}

// At a fixed control-point count, moving the knots beats leaving them averaged.
TEST(FitSurface, OptimisedKnotsBeatAveragedKnotsAtTheRidge) {
  const GridSamples grid = ridge_grid();
  SurfaceFitOptions fixed;
  fixed.optimise_knots = false;
  const SurfaceFit averaged = fit_surface(grid, 12, 6, fixed);
  const SurfaceFit optimised = fit_surface(grid, 12, 6, SurfaceFitOptions{});
  std::printf("ridge 12 x 6: max error averaged %.3g, optimised %.3g; rms %.3g, %.3g (%d iterations)\n",
              averaged.max_error, optimised.max_error, averaged.rms_error, optimised.rms_error, optimised.iterations);
  EXPECT_EQ(averaged.iterations, 0);
  EXPECT_GT(optimised.iterations, 0);
  EXPECT_LT(optimised.rms_error, 0.5 * averaged.rms_error);
  EXPECT_LT(optimised.max_error, averaged.max_error);
}

void expect_refusal(const std::function<void()>& call, const std::string& message) {
  try {
    call();
    ADD_FAILURE() << "no refusal, expected: " << message;
  } catch (const std::invalid_argument& error) {
    EXPECT_EQ(std::string(error.what()), message);
  }
}

TEST(FitSurface, RefusesWhatItCannotFit) {
  const GridSamples good = sample_grid(10, 8, wave);
  const SurfaceFitOptions options;
  expect_refusal([&] { fit_surface(GridSamples{}, 4, 4, options); }, "fit_surface: no samples");
  GridSamples short_points = good;
  short_points.points.pop_back();
  expect_refusal([&] { fit_surface(short_points, 4, 4, options); }, "fit_surface: 10 x 8 parameters for 79 points");
  GridSamples outside = good;
  outside.v[7] = 1.5;
  expect_refusal([&] { fit_surface(outside, 4, 4, options); }, "fit_surface: v parameter 7 (1.5) is not in [0, 1]");
  GridSamples repeated = good;
  repeated.u[4] = repeated.u[3];
  expect_refusal([&] { fit_surface(repeated, 4, 4, options); }, "fit_surface: u parameter 4 does not increase");
  GridSamples not_finite = good;
  not_finite.points[13].y() = std::nan("");
  expect_refusal([&] { fit_surface(not_finite, 4, 4, options); }, "fit_surface: point 13 is not finite");
  SurfaceFitOptions order_one;
  order_one.v_order = 1;
  expect_refusal([&] { fit_surface(good, 4, 4, order_one); }, "fit_surface: v order 1 is not in 2..16");
  expect_refusal([&] { fit_surface(good, 3, 4, options); }, "fit_surface: 3 u control points are fewer than the u order 4");
  expect_refusal([&] { fit_surface(good, 4, 9, options); },
                 "fit_surface: 9 v control points need at least as many v parameters (8)");
  SurfaceFitOptions wide_gap;
  wide_gap.minimum_knot_gap = 0.3;
  expect_refusal([&] { fit_surface(good, 7, 4, wide_gap); },
                 "fit_surface: 4 u spans do not fit in [0, 1] at the minimum knot gap 0.3");
  expect_refusal([&] { fit_surface_within(good, 0, options); }, "fit_surface_within: the tolerance must be > 0");
  SurfaceFitOptions high_order;
  high_order.u_order = 12;
  expect_refusal([&] { fit_surface_within(good, 1e-3, high_order); },
                 "fit_surface_within: 10 u parameters cannot fix a surface of u order 12");
  // Noise no spline with fewer control points than samples can follow: the refinement runs out of
  // parameters and says so.
  GridSamples noisy = good;
  for (size_t k = 0; k < noisy.points.size(); ++k) noisy.points[k].z() += (k * 7919 % 13) * 0.01;
  expect_refusal([&] { fit_surface_within(noisy, 1e-6, options); },
                 "fit_surface_within: the data cannot be met within 1e-06: the refinement would need 12 u control points, "
                 "more than the 10 u parameters (max error still 0.0629)");
}

}  // namespace
}  // namespace cadnurbs
