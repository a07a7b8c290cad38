#include <gtest/gtest.h>

#include <random>

#include "core/bezier_extraction.hpp"
#include "core/geometry_error.hpp"
#include "core/nurbs_surface.hpp"
#include "test_shapes.hpp"

using namespace cadnurbs;

TEST(Surface, QuarterCylinderPointsLieAtTheRadius) {
  const NurbsSurface s = test::quarter_cylinder(3.0, 2.0);
  validate(s, "cylinder");
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 1000; ++i) {
    const double u = unit(rng), v = unit(rng);
    const Eigen::Vector3d p = surface_point(s, u, v);
    EXPECT_NEAR(p.head<2>().norm(), 3.0, 1e-12);
    EXPECT_NEAR(p.z(), 2.0 * v, 1e-12);
  }
}

TEST(Surface, NormalOfCylinderIsRadial) {
  const NurbsSurface s = test::quarter_cylinder(3.0, 2.0);
  for (double u : {0.0, 0.3, 0.77, 1.0}) {
    const Eigen::Vector3d p = surface_point(s, u, 0.5);
    const Eigen::Vector3d n = surface_normal(s, u, 0.5);
    const Eigen::Vector3d radial(p.x(), p.y(), 0);
    EXPECT_NEAR(std::abs(n.dot(radial.normalized())), 1.0, 1e-12);
  }
}

TEST(Surface, DerivativesMatchCentralDifferences) {
  NurbsSurface s;
  s.u_order = 3;
  s.v_order = 4;
  s.u_count = 4;
  s.v_count = 5;
  s.u_knots = {0, 0, 0, 0.4, 1, 1, 1};
  s.v_knots = {0, 0, 0, 0, 0.5, 1, 1, 1, 1};
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> r(-1, 1), w(0.5, 2);
  for (int k = 0; k < 20; ++k) {
    s.points.push_back({(k % 4) + 0.3 * r(rng), (k / 4) + 0.3 * r(rng), r(rng)});
    s.weights.push_back(w(rng));
  }
  validate(s, "s");
  const double h = 1e-4;
  for (auto [u, v] : {std::pair{0.2, 0.3}, {0.6, 0.7}, {0.9, 0.1}}) {
    const auto d = surface_derivatives(s, u, v, 2);
    auto p = [&](double a, double b) { return surface_point(s, a, b); };
    const Eigen::Vector3d su = (p(u + h, v) - p(u - h, v)) / (2 * h);
    const Eigen::Vector3d sv = (p(u, v + h) - p(u, v - h)) / (2 * h);
    const Eigen::Vector3d suu = (p(u + h, v) - 2 * p(u, v) + p(u - h, v)) / (h * h);
    const Eigen::Vector3d svv = (p(u, v + h) - 2 * p(u, v) + p(u, v - h)) / (h * h);
    const Eigen::Vector3d suv = (p(u + h, v + h) - p(u + h, v - h) - p(u - h, v + h) + p(u - h, v - h)) / (4 * h * h);
    EXPECT_LT((d[1][0] - su).norm(), 1e-6 * (1 + su.norm()));
    EXPECT_LT((d[0][1] - sv).norm(), 1e-6 * (1 + sv.norm()));
    EXPECT_LT((d[2][0] - suu).norm(), 1e-4 * (1 + suu.norm()));
    EXPECT_LT((d[0][2] - svv).norm(), 1e-4 * (1 + svv.norm()));
    EXPECT_LT((d[1][1] - suv).norm(), 1e-4 * (1 + suv.norm()));
  }
}

TEST(Surface, BezierPatchesReproduceTheSurface) {
  NurbsSurface s = test::quarter_cylinder(1.0, 1.0);
  // Make it two spans in each direction by inserting knots first through a wider surface.
  s.v_order = 2;
  const auto patches = bezier_patches(s);
  ASSERT_EQ(patches.size(), 1u);
  for (double u : {0.1, 0.5, 0.9})
    EXPECT_LT((surface_point(patches[0], u, 0.5) - surface_point(s, u, 0.5)).norm(), 1e-14);
}

TEST(Surface, RefusesPointCountMismatch) {
  NurbsSurface s = test::quarter_cylinder(1.0, 1.0);
  s.points.pop_back();
  try {
    validate(s, "lid");
    FAIL();
  } catch (const GeometryError& e) {
    EXPECT_STREQ(e.what(), "lid: 5 control points given, but 3 x 2 = 6 needed");
  }
}

TEST(Surface, RefusesNegativeWeight) {
  NurbsSurface s = test::quarter_cylinder(1.0, 1.0);
  s.weights[4] = -0.5;
  try {
    validate(s, "body");
    FAIL();
  } catch (const GeometryError& e) {
    EXPECT_STREQ(e.what(), "body: weight 4 is -0.500000; weights must be positive");
  }
}

TEST(Surface, RefusesBadKnotVectorInV) {
  NurbsSurface s = test::quarter_cylinder(1.0, 1.0);
  s.v_knots = {0, 0, 1};
  try {
    validate(s, "body");
    FAIL();
  } catch (const GeometryError& e) {
    EXPECT_STREQ(e.what(), "body: v: 3 knots given, but 2 control points of order 2 need 4");
  }
}
