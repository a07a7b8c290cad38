// tessellation_hints against closed forms and against the uniform grids the viewers build.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "analysis/tessellation/plan_tessellation_hints.hpp"
#include "analysis_shapes.hpp"

namespace cadnurbs {
namespace {

// Segments a viewer takes from a hint (0: its default, 2 x control points).
int viewer_count(int hint, int control_points) { return hint > 0 ? hint : 2 * control_points; }

// Largest distance to the exact surface (`distance`) of the triangles of the uniform n_u x n_v grid a
// viewer builds (X_ITE's diagonal), sampled at 7 x 7 barycentric points a triangle.
double grid_deviation(const NurbsSurface& s, int nu, int nv, const std::function<double(const Eigen::Vector3d&)>& distance) {
  const double u0 = s.u_start(), u1 = s.u_end(), v0 = s.v_start(), v1 = s.v_end();
  auto at = [&](int i, int j) { return surface_point(s, u0 + (u1 - u0) * i / nu, v0 + (v1 - v0) * j / nv); };
  double worst = 0;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const Eigen::Vector3d p0 = at(i, j), p1 = at(i + 1, j), p2 = at(i + 1, j + 1), p3 = at(i, j + 1);
      for (const auto& [a, b, c] : {std::tuple{p0, p1, p2}, std::tuple{p0, p2, p3}})
        for (int x = 0; x <= 6; ++x)
          for (int y = 0; x + y <= 6; ++y) {
            const double l1 = x / 6.0, l2 = y / 6.0;
            worst = std::max(worst, distance((1 - l1 - l2) * a + l1 * b + l2 * c));
          }
    }
  return worst;
}

TEST(TessellationHints, QuarterCylinderMeetsTheSagittaAndIsNotWasteful) {
  const double radius = 10, height = 5;
  const TrimmedSurface face = test::quarter_cylinder(radius, height);
  for (const double d : {0.1, 0.01, 0.001}) {
    const TessellationHints h = plan_tessellation_hints(face, d);
    const int nu = viewer_count(h.u, 3), nv = viewer_count(h.v, 2);
    // n chords over the quarter circle, each of angle pi / (2n): sagitta R (1 - cos(pi / (4n))) at
    // equal angles; the viewer's chords are equal in the parameter, not in angle, so it needs a bit
    // more: measured below on its grid.
    int minimum = 1;
    while (radius * (1 - std::cos(M_PI / (4 * minimum))) > d) ++minimum;
    std::printf("  D %-6g u %d (%d segments; fewest by the sagitta %d) v %d\n", d, h.u, nu, minimum, h.v);
    EXPECT_LE(radius * (1 - std::cos(M_PI / (4 * nu))), d);
    EXPECT_LE(nu, 2 * minimum + 1);
    EXPECT_LE(h.v, 1) << "the straight direction needs no steps";
    EXPECT_LE(grid_deviation(face.surface, nu, nv, [&](const Eigen::Vector3d& p) { return test::distance_to_cylinder(p, radius); }), d);
  }
}

TEST(TessellationHints, BilinearPlaneNeedsNothing) {
  const TrimmedSurface face = test::trimmed_square(10, 0.4, 0.1);
  const TessellationHints h = plan_tessellation_hints(face, 1e-6);
  EXPECT_TRUE(h.u == 0 || h.u == 1);
  EXPECT_TRUE(h.v == 0 || h.v == 1);
}

TEST(TessellationHints, TorusPatchGridWithinDeviation) {
  const double major = 40, minor = 10;
  const TrimmedSurface face = test::torus_patch(major, minor);
  for (const double d : {0.1, 0.01}) {
    const TessellationHints h = plan_tessellation_hints(face, d);
    const int nu = viewer_count(h.u, 3), nv = viewer_count(h.v, 3);
    const double measured =
        grid_deviation(face.surface, nu, nv, [&](const Eigen::Vector3d& p) { return test::distance_to_torus(p, major, minor); });
    std::printf("  D %-6g u %d v %d: measured %.3g\n", d, nu, nv, measured);
    EXPECT_LE(measured, d);
    EXPECT_LE(nu, kMaxSurfaceTessellation);
    EXPECT_LE(nv, kMaxSurfaceTessellation);
  }
}

TEST(TessellationHints, KinkedParametrisationIsBoundedAcrossTheKnot) {
  // A full circle of 4 rational arcs has C0 knots where the parametrisation is C1 after all (equal
  // speed on both sides): no kink term. The sphere's grid must still come within D.
  const double radius = 20, d = 0.01;
  const TrimmedSurface face = test::sphere(radius);
  const TessellationHints h = plan_tessellation_hints(face, d);
  const int nu = viewer_count(h.u, 9), nv = viewer_count(h.v, 5);
  const double measured = grid_deviation(face.surface, nu, nv, [&](const Eigen::Vector3d& p) { return test::distance_to_sphere(p, radius); });
  std::printf("  sphere D %g: u %d v %d, measured %.3g\n", d, nu, nv, measured);
  EXPECT_LE(measured, d);
  // A parametrisation that really kinks: a corner of two straight pieces of speed 1 and 2.
  NurbsCurve kinked;
  kinked.dimension = 2, kinked.order = 2;
  kinked.knots = {0, 0, 1, 1.5, 1.5};
  kinked.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
  // n = 3 samples 0, 0.5, 1, 1.5: the corner is a sample, the chords are exact
  EXPECT_EQ(uniform_chord_deviation_bound(kinked, 3), 0.0);
  // n = 2 samples 0, 0.75, 1.5: the second chord cuts the corner; the bound covers the parametric
  // error (chord point against curve point at the same parameter), which covers the distance
  const double bound2 = uniform_chord_deviation_bound(kinked, 2);
  double worst = 0;
  for (int k = 0; k <= 300; ++k) {
    const double t = 0.75 + 0.75 * k / 300;
    const Eigen::Vector3d chord = curve_point(kinked, 0.75) + (curve_point(kinked, 1.5) - curve_point(kinked, 0.75)) * ((t - 0.75) / 0.75);
    worst = std::max(worst, (chord - curve_point(kinked, t)).norm());
  }
  std::printf("  kinked corner: bound %.4f, parametric error %.4f\n", bound2, worst);
  EXPECT_GE(bound2, worst);
  EXPECT_LE(bound2, 2 * worst);
}

TEST(TessellationHints, TrimmingCircleChordsWithinDeviationIn3D) {
  // Square of side 100 trimmed by a circle of radius 40 with a hole of radius 15 (in (u,v) 0.4, 0.15).
  const double size = 100;
  const TrimmedSurface face = test::trimmed_square(size, 0.4, 0.15);
  for (const double d : {0.1, 0.01}) {
    const TessellationHints h = plan_tessellation_hints(face, d);
    ASSERT_EQ(h.trim_segments.size(), 2u);
    for (int loop = 0; loop < 2; ++loop) {
      const NurbsCurve& c = std::get<NurbsCurve>(face.loops[loop].segments[0]);
      const double r = size * (loop == 0 ? 0.4 : 0.15);
      // largest distance of the 3D curve from its chord, over the n uniform chords a viewer draws
      auto chord_error = [&](int n) {
        double worst = 0;
        const double a = c.domain_start(), b = c.domain_end();
        for (int i = 0; i < n; ++i) {
          const double t0 = a + (b - a) * i / n, t1 = a + (b - a) * (i + 1) / n;
          const Eigen::Vector3d p = size * curve_point(c, t0), q = size * curve_point(c, t1);
          for (int k = 0; k <= 40; ++k) {
            const Eigen::Vector3d x = size * curve_point(c, t0 + (t1 - t0) * k / 40.0);
            const double len2 = (q - p).squaredNorm();
            const double f = len2 > 0 ? std::clamp((x - p).dot(q - p) / len2, 0.0, 1.0) : 0.0;
            worst = std::max(worst, (x - (p + f * (q - p))).norm());
          }
        }
        return worst;
      };
      const int n = viewer_count(h.trim_segments[loop][0], c.count());
      int minimum = 1;
      while (chord_error(minimum) > d) ++minimum;
      std::printf("  D %-5g loop %d radius %g: %d chords (fewest within D: %d)\n", d, loop, r, n, minimum);
      EXPECT_LE(chord_error(n), d);
      EXPECT_LE(n, 3 * minimum);
    }
  }
}

TEST(TessellationHints, PolylineSegmentsGetZeroAndBadDeviationIsRefused) {
  TrimmedSurface face = test::quarter_cylinder(1, 1);
  TrimLoop loop;
  loop.segments.emplace_back(Polyline2D{{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}}});
  face.loops.push_back(loop);
  const TessellationHints h = plan_tessellation_hints(face, 0.001);
  ASSERT_EQ(h.trim_segments.size(), 1u);
  EXPECT_EQ(h.trim_segments[0], std::vector<int>{0});
  EXPECT_THROW(plan_tessellation_hints(face, 0.0), std::invalid_argument);
  EXPECT_THROW(plan_tessellation_hints(face, std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace cadnurbs
