#include "core/nearest_surface_point.hpp"

#include <gtest/gtest.h>

#include <random>

#include "fit_test_shapes.hpp"

using namespace cadnurbs;

namespace {

// S(u,v) inverted back to (u,v), globally and from a start 0.15 of the domain away; u compared modulo
// `u_period` on a closed surface (its seam's points have two (u,v), both right).
void expect_round_trip(const NurbsSurface& s, int count, double u_period = 0.0) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Eigen::Vector2d lo(s.u_start(), s.v_start()), size(s.u_end() - s.u_start(), s.v_end() - s.v_start());
  for (int k = 0; k < count; ++k) {
    Eigen::Vector2d uv = lo + Eigen::Vector2d(unit(rng), unit(rng)).cwiseProduct(size);
    if (k % 10 == 0) uv.x() = lo.x();  // on a side too
    const Eigen::Vector3d p = surface_point(s, uv.x(), uv.y());
    Eigen::Vector2d global = nearest_surface_parameter(s, p);
    if (u_period > 0) global.x() -= u_period * std::round((global.x() - uv.x()) / u_period);
    EXPECT_LT((global - uv).norm(), 1e-10) << uv.transpose() << " -> " << global.transpose();
    const Eigen::Vector2d start = uv + 0.15 * size.cwiseProduct(Eigen::Vector2d(unit(rng) - 0.5, unit(rng) - 0.5));
    const Eigen::Vector2d local = nearest_surface_parameter(s, p, start);
    EXPECT_LT((local - uv).norm(), 1e-10) << uv.transpose() << " from " << start.transpose();
  }
}

}  // namespace

TEST(NearestSurfacePoint, RationalQuarterCylinderRoundTrip) { expect_round_trip(test::quarter_cylinder(2.0, 3.0), 300); }

TEST(NearestSurfacePoint, FullCylinderRoundTrip) { expect_round_trip(test::full_cylinder(1.0, 3.0), 300, 4.0); }

TEST(NearestSurfacePoint, BicubicPatchRoundTrip) { expect_round_trip(test::bicubic_patch(), 300); }

TEST(NearestSurfacePoint, PointsOffTheSurfaceFindTheirFoot) {
  const NurbsSurface s = test::quarter_cylinder(2.0, 3.0);
  for (double offset : {-0.7, -0.01, 0.01, 1.5}) {
    const Eigen::Vector2d uv(0.37, 0.61);
    const Eigen::Vector3d p = surface_point(s, uv.x(), uv.y()) + offset * surface_normal(s, uv.x(), uv.y());
    EXPECT_LT((nearest_surface_parameter(s, p) - uv).norm(), 1e-10) << offset;
  }
  const NurbsSurface patch = test::bicubic_patch();
  const Eigen::Vector2d uv(1.1, 0.55);
  const Eigen::Vector3d p = surface_point(patch, uv.x(), uv.y()) + 0.05 * surface_normal(patch, uv.x(), uv.y());
  EXPECT_LT((nearest_surface_parameter(patch, p) - uv).norm(), 1e-10);
}

TEST(NearestSurfacePoint, PointsBeyondASideGoToTheSide) {
  // At 100 degrees, beyond the quarter cylinder's end at 90 (u = 1): the nearest point is on that side.
  const NurbsSurface s = test::quarter_cylinder(2.0, 3.0);
  const double a = 100.0 * M_PI / 180.0;
  const Eigen::Vector3d p(2.0 * std::cos(a), 2.0 * std::sin(a), 1.5);
  for (const Eigen::Vector2d& uv : {nearest_surface_parameter(s, p), nearest_surface_parameter(s, p, {0.2, 0.9})}) {
    EXPECT_EQ(uv.x(), 1.0);
    EXPECT_NEAR(uv.y(), 0.5, 1e-12);
  }
}

TEST(NearestSurfacePoint, NonFinitePointReturnsTheClampedStart) {
  const NurbsSurface s = test::quarter_cylinder(2.0, 3.0);
  const Eigen::Vector3d p(NAN, 0, 0);
  EXPECT_EQ(nearest_surface_parameter(s, p, {0.5, 7.0}), Eigen::Vector2d(0.5, 1.0));
  EXPECT_TRUE(nearest_surface_parameter(s, p).allFinite());
}
