// surface_deviation_bound and triangle_deviation_bound against closed forms: the bound of a triangle is
// never below the true distance between the surface and its linear interpolant (a sphere's sagitta, a
// cylinder's), is FMM's grid-cell formula on a right triangle, and is zero on a plane.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "analysis/eval/surface_deviation_bound.hpp"
#include "analysis/eval/surface_evaluator.hpp"
#include "analysis_shapes.hpp"

namespace cadnurbs {
namespace {

double bound_over_triangle(const SurfaceDeviationBound& bound, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                           const Eigen::Vector2d& c) {
  const auto m = bound.over(std::min({a.x(), b.x(), c.x()}), std::max({a.x(), b.x(), c.x()}), std::min({a.y(), b.y(), c.y()}),
                            std::max({a.y(), b.y(), c.y()}));
  return triangle_deviation_bound(a, b, c, m);
}

// Largest |S - L| over the triangle, L the linear interpolant of S at its corners: sampled on a
// lattice of n divisions (a lower bound of the true maximum).
double sampled_interpolation_error(const SurfaceEvaluator& e, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                   const Eigen::Vector2d& c, int n) {
  const Eigen::Vector3d pa = e.point(a.x(), a.y()), pb = e.point(b.x(), b.y()), pc = e.point(c.x(), c.y());
  double worst = 0;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      const double la = static_cast<double>(n - i - j) / n, lb = static_cast<double>(i) / n, lc = static_cast<double>(j) / n;
      const Eigen::Vector2d uv = la * a + lb * b + lc * c;
      worst = std::max(worst, (e.point(uv.x(), uv.y()) - (la * pa + lb * pb + lc * pc)).norm());
    }
  return worst;
}

TEST(SurfaceDeviationBound, SpherePatchBoundIsAtLeastItsTrueSagitta) {
  const double radius = 50;
  const TrimmedSurface sphere = test::sphere(radius);
  const SurfaceDeviationBound bound = surface_deviation_bound(sphere.surface);
  // Patches: u 4 quarter circles, v 2 quarter meridians; C0 lines between them.
  EXPECT_EQ(bound.u_breaks, (std::vector<double>{0, 1, 2, 3, 4}));
  EXPECT_EQ(bound.v_breaks, (std::vector<double>{0, 1, 2}));
  EXPECT_EQ(bound.c0_u, (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(bound.c0_v, (std::vector<double>{1}));
  ASSERT_EQ(bound.patches.size(), 8u);
  // A triangle with one side along the equator over a whole quarter arc (v = 1, u from 0 to 1): at the
  // side's middle the symmetric rational arc is at its own middle, and L at the chord's middle, so
  // |S - L| there is the arc's sagitta R (1 - cos 45 deg), exactly.
  for (double height : {1.0, 0.5, 0.1}) {
    const Eigen::Vector2d a(0, 1), b(1, 1), c(0, 1 + height);
    const double sagitta = radius * (1 - std::cos(M_PI / 4));
    const double b_abc = bound_over_triangle(bound, a, b, c);
    std::printf("  height %-4g bound %.4g, sagitta %.4g (%.2fx)\n", height, b_abc, sagitta, b_abc / sagitta);
    EXPECT_GE(b_abc, sagitta) << "height " << height;
  }
  // Small triangles inside a patch: never below the sampled error; and as sharp as the sphere's own
  // sagitta over a chord of length l, about l^2 / (8 R), up to a constant factor (16: the quotient-rule
  // bounds of a rational patch) that does not grow as the triangle shrinks.
  const SurfaceEvaluator e(sphere.surface);
  for (double h : {0.2, 0.05, 0.0125}) {
    const Eigen::Vector2d a(0.3, 1.2), b(0.3 + h, 1.2), c(0.3, 1.2 + h);
    const double b_abc = bound_over_triangle(bound, a, b, c);
    const double sampled = sampled_interpolation_error(e, a, b, c, 24);
    EXPECT_GE(b_abc, sampled) << "h " << h;
    const double longest = std::max({(e.point(b.x(), b.y()) - e.point(a.x(), a.y())).norm(),
                                     (e.point(c.x(), c.y()) - e.point(b.x(), b.y())).norm(),
                                     (e.point(a.x(), a.y()) - e.point(c.x(), c.y())).norm()});
    EXPECT_LE(b_abc, 16 * longest * longest / (8 * radius)) << "h " << h;
  }
}

TEST(SurfaceDeviationBound, CylinderBoundCoversTheArcAndIsZeroAlongTheAxis) {
  const double radius = 20;
  const TrimmedSurface cylinder = test::quarter_cylinder(radius, 40);
  const SurfaceDeviationBound bound = surface_deviation_bound(cylinder.surface);
  ASSERT_EQ(bound.patches.size(), 1u);
  EXPECT_EQ(bound.patches[0].vv, 0.0);  // straight along the axis
  // A sliver along the axis (no extent in u) has nothing to bound.
  EXPECT_EQ(bound_over_triangle(bound, {0.5, 0}, {0.5, 1}, {0.5, 0.5}), 0.0);
  // The whole quarter arc as one side: its sagitta R (1 - cos 45 deg) is the true error there.
  EXPECT_GE(bound_over_triangle(bound, {0, 0}, {1, 0}, {0, 1}), radius * (1 - std::cos(M_PI / 4)));
  // A right triangle of an h_u x h_v cell: FMM's (1/8)(h_u^2 M_uu + 2 h_u h_v M_uv + h_v^2 M_vv).
  const double hu = 0.25, hv = 0.5;
  const auto& m = bound.patches[0];
  EXPECT_NEAR(triangle_deviation_bound({0, 0}, {hu, 0}, {0, hv}, m),
              (hu * hu * m.uu + 2 * hu * hv * m.uv + hv * hv * m.vv) / 8, 1e-12 * m.uu);
}

TEST(SurfaceDeviationBound, APlaneHasNoDeviation) {
  const TrimmedSurface square = test::trimmed_square(100, 0.4, 0.15);
  const SurfaceDeviationBound bound = surface_deviation_bound(square.surface);
  ASSERT_EQ(bound.patches.size(), 1u);
  EXPECT_EQ(bound.patches[0].uu, 0.0);
  EXPECT_EQ(bound.patches[0].vv, 0.0);
  EXPECT_EQ(bound_over_triangle(bound, {0, 0}, {1, 0}, {0.3, 1}), 0.0);
}

}  // namespace
}  // namespace cadnurbs
