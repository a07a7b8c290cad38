// Knot removal on curves and surfaces, polynomial and rational, against closed forms: what knot
// refinement added comes back off exactly, a perturbed net stays within the tolerance, and a net whose
// knots are all needed is returned as it was.
#include "core/knot_removal.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "analysis_shapes.hpp"
#include "core/knot_insertion.hpp"
#include "core/knot_vector.hpp"

namespace cadnurbs {
namespace {

// A bicubic x biquadratic patch over [0,1]^2 with an uneven net (5 x 4 points).
NurbsSurface wavy_patch() {
  NurbsSurface s;
  s.u_order = 4;
  s.v_order = 3;
  s.u_count = 5;
  s.v_count = 4;
  s.u_knots = {0, 0, 0, 0, 0.4, 1, 1, 1, 1};
  s.v_knots = clamped_uniform_knots(3, 4);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 5; ++i) s.points.emplace_back(i, j + 0.3 * i, std::sin(1.3 * i) * std::cos(0.9 * j));
  return s;
}

// Largest distance between two surfaces with one domain, at the same parameters on an n x n grid.
double grid_distance(const NurbsSurface& a, const NurbsSurface& b, int n = 60) {
  double worst = 0;
  for (int p = 0; p <= n; ++p)
    for (int q = 0; q <= n; ++q) {
      const double u = a.u_start() + (a.u_end() - a.u_start()) * p / n;
      const double v = a.v_start() + (a.v_end() - a.v_start()) * q / n;
      worst = std::max(worst, (surface_point(a, u, v) - surface_point(b, u, v)).norm());
    }
  return worst;
}

TEST(KnotRemoval, RefinedPolynomialSurfaceComesBackToItsNet) {
  const NurbsSurface original = wavy_patch();
  const NurbsSurface refined = refine_knots(refine_knots(original, SurfaceDirection::u, {0.1, 0.25, 0.4, 0.7}),
                                            SurfaceDirection::v, {0.2, 0.5, 0.8});
  ASSERT_EQ(refined.u_count * refined.v_count, 9 * 7);
  int removed = 0;
  const NurbsSurface back = remove_knots(refined, 1e-9, &removed);
  EXPECT_EQ(removed, 7);
  EXPECT_EQ(back.u_count, original.u_count);
  EXPECT_EQ(back.v_count, original.v_count);
  EXPECT_EQ(back.u_knots, original.u_knots);
  EXPECT_LT(grid_distance(original, back), 1e-9);
  for (size_t k = 0; k < original.points.size(); ++k) EXPECT_LT((back.points[k] - original.points[k]).norm(), 1e-9);
}

TEST(KnotRemoval, RefinedRationalCylinderQuarterComesBackToItsNet) {
  const TrimmedSurface quarter = test::quarter_cylinder(3.0, 2.0);
  const NurbsSurface& original = quarter.surface;
  ASSERT_TRUE(original.is_rational());
  const auto inside = [](const std::vector<double>& knots, std::vector<double> fractions) {
    for (auto& f : fractions) f = knots.front() + (knots.back() - knots.front()) * f;
    return fractions;
  };
  const NurbsSurface refined =
      refine_knots(refine_knots(original, SurfaceDirection::u, inside(original.u_knots, {0.2, 0.5, 0.5, 0.85})),
                   SurfaceDirection::v, inside(original.v_knots, {0.3, 0.6}));
  ASSERT_EQ(refined.u_count, original.u_count + 4);
  int removed = 0;
  const NurbsSurface back = remove_knots(refined, 1e-9, &removed);
  EXPECT_EQ(removed, 6);
  EXPECT_EQ(back.u_count, original.u_count);
  EXPECT_EQ(back.v_count, original.v_count);
  EXPECT_LT(grid_distance(original, back), 1e-9);
  for (size_t k = 0; k < original.weights.size(); ++k) EXPECT_NEAR(back.weights[k], original.weights[k], 1e-9);
  // On the cylinder itself (closed form), not only near the input.
  for (int p = 0; p <= 40; ++p)
    for (int q = 0; q <= 10; ++q) {
      const double u = back.u_start() + (back.u_end() - back.u_start()) * p / 40;
      const double v = back.v_start() + (back.v_end() - back.v_start()) * q / 10;
      EXPECT_LT(test::distance_to_cylinder(surface_point(back, u, v), 3.0), 1e-9);
    }
}

TEST(KnotRemoval, RefinedRationalArcComesBackToThreePoints) {
  NurbsCurve arc;
  arc.order = 3;
  arc.knots = {0, 0, 0, 1, 1, 1};
  arc.points = {{2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  arc.weights = {1, std::sqrt(0.5), 1};
  const NurbsCurve refined = refine_knots(arc, {0.1, 0.3, 0.3, 0.6, 0.9});
  int removed = 0;
  const NurbsCurve back = remove_knots(refined, 1e-9, &removed);
  EXPECT_EQ(removed, 5);
  ASSERT_EQ(back.count(), 3);
  for (int k = 0; k <= 200; ++k) EXPECT_NEAR(curve_point(back, k / 200.0).norm(), 2.0, 1e-9);
  EXPECT_NEAR(back.weights[1], std::sqrt(0.5), 1e-9);
}

TEST(KnotRemoval, PerturbedRefinedSurfaceLosesKnotsAndStaysWithinTheTolerance) {
  const double tolerance = 0.01;
  const NurbsSurface original = wavy_patch();
  std::vector<double> extra;
  for (int k = 1; k < 12; ++k) extra.push_back(k / 12.0);
  NurbsSurface noisy = refine_knots(refine_knots(original, SurfaceDirection::u, extra), SurfaceDirection::v, extra);
  std::mt19937 random(15);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (auto& q : noisy.points) {
    Eigen::Vector3d step(unit(random), unit(random), unit(random));
    q += 0.1 * tolerance * step.normalized();
  }
  int removed = 0;
  const NurbsSurface simpler = remove_knots(noisy, tolerance, &removed);
  EXPECT_GT(removed, 0);
  EXPECT_LT(simpler.u_count * simpler.v_count, noisy.u_count * noisy.v_count);
  EXPECT_EQ(simpler.u_count + simpler.v_count, noisy.u_count + noisy.v_count - removed);
  EXPECT_LE(grid_distance(noisy, simpler, 150), tolerance);

  // The same with weights: a refined cylinder quarter (rational quadratic arcs) with its points moved.
  const NurbsSurface quarter = test::quarter_cylinder(3.0, 2.0).surface;
  const auto spread = [&extra](const std::vector<double>& knots) {
    std::vector<double> t;
    for (double f : extra) t.push_back(knots.front() + (knots.back() - knots.front()) * f);
    return t;
  };
  NurbsSurface weighted = refine_knots(refine_knots(quarter, SurfaceDirection::u, spread(quarter.u_knots)),
                                       SurfaceDirection::v, spread(quarter.v_knots));
  for (auto& q : weighted.points) {
    Eigen::Vector3d step(unit(random), unit(random), unit(random));
    q += 0.1 * tolerance * step.normalized();
  }
  const NurbsSurface rational = remove_knots(weighted, tolerance, &removed);
  EXPECT_GT(removed, 0);
  EXPECT_EQ(rational.u_count + rational.v_count, weighted.u_count + weighted.v_count - removed);
  EXPECT_LE(grid_distance(weighted, rational, 150), tolerance);
  std::printf("perturbed %dx%d net: %dx%d; perturbed %dx%d cylinder quarter: %dx%d\n", noisy.u_count, noisy.v_count,
              simpler.u_count, simpler.v_count, weighted.u_count, weighted.v_count, rational.u_count, rational.v_count);
}

TEST(KnotRemoval, SurfaceWhoseKnotsAreAllNeededComesBackUnchanged) {
  // A random bicubic net: every knot carries shape far above the tolerance.
  NurbsSurface rough;
  rough.u_order = rough.v_order = 4;
  rough.u_count = rough.v_count = 8;
  rough.u_knots = rough.v_knots = clamped_uniform_knots(4, 8);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) rough.points.emplace_back(i, j, unit(random));
  int removed = -1;
  const NurbsSurface same = remove_knots(rough, 1e-4, &removed);
  EXPECT_EQ(removed, 0);
  EXPECT_EQ(same.u_knots, rough.u_knots);
  EXPECT_EQ(same.v_knots, rough.v_knots);
  EXPECT_EQ(same.points, rough.points);

  // A sphere's arcs (double knots at quarter turns) are exact and minimal: nothing goes at 1e-4 r.
  const NurbsSurface sphere = test::sphere(1.0).surface;
  const NurbsSurface kept = remove_knots(sphere, 1e-4, &removed);
  EXPECT_EQ(removed, 0);
  EXPECT_EQ(kept.u_count, sphere.u_count);
  EXPECT_EQ(kept.v_count, sphere.v_count);
  EXPECT_EQ(kept.weights, sphere.weights);
}

}  // namespace
}  // namespace cadnurbs
