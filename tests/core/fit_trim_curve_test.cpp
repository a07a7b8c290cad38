#include "core/fit_trim_curve.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <string>

#include "core/geometry_error.hpp"
#include "core/interpolate_curve.hpp"
#include "core/nearest_surface_point.hpp"
#include "fit_test_shapes.hpp"

using namespace cadnurbs;

namespace {

constexpr double kPeriod = 4.0;  // the full cylinder's u period

double wrapped(double u) { return u - kPeriod * std::floor(u / kPeriod); }

// A face on the full cylinder as the STEP builder sees it: u unwrapped to stay continuous along a curve,
// Newton from the previous sample, the global search where Newton stops away from the point (it stops at
// the seam's side when the point lies just across it).
struct CylinderFace {
  NurbsSurface surface = test::full_cylinder(1.0, 3.0);
  Eigen::Vector2d locate(const Eigen::Vector3d& p, const Eigen::Vector2d& previous) const {
    const Eigen::Vector2d start(wrapped(previous.x()), previous.y());
    Eigen::Vector2d uv = nearest_surface_parameter(surface, p, start);
    if ((surface_point(surface, uv.x(), uv.y()) - p).norm() > 1e-9) uv = nearest_surface_parameter(surface, p);
    uv.x() += kPeriod * std::round((previous.x() - uv.x()) / kPeriod);
    return uv;
  }
  Eigen::Vector3d at(const Eigen::Vector2d& uv) const { return surface_point(surface, wrapped(uv.x()), uv.y()); }
  LocateOnSurface locator() const {
    return [this](const Eigen::Vector3d& p, const Eigen::Vector2d& previous) { return locate(p, previous); };
  }
  SurfaceAt evaluator() const {
    return [this](const Eigen::Vector2d& uv) { return at(uv); };
  }
};

// The oblique cut of the radius-1 cylinder by the plane z = 1.5 + 0.5 x: an ellipse, exactly rational
// (an affine image of the 9-point circle, turned by 0.3 rad so that it starts off the seam and crosses it).
NurbsCurve oblique_ellipse(double scale = 1.0) {
  NurbsCurve c = test::full_circle(1.0);
  const Eigen::Rotation2Dd turn(0.3);
  for (Eigen::Vector3d& p : c.points) {
    const Eigen::Vector2d xy = scale * (turn * p.head<2>());
    p = Eigen::Vector3d(xy.x(), xy.y(), 1.5 + 0.5 * xy.x());
  }
  return c;
}

// A helix of radius 1 on the cylinder, 1.5 turns rising 2: a cubic interpolant of 600 of its points (off
// the cylinder by ~1e-10, checked below).
NurbsCurve helix() {
  std::vector<Eigen::Vector3d> points;
  std::vector<double> t;
  for (int k = 0; k <= 600; ++k) {
    const double a = 0.2 + 3 * M_PI * k / 600.0;
    points.emplace_back(std::cos(a), std::sin(a), 0.4 + 2.0 * k / 600.0);
    t.push_back(k / 600.0);
  }
  return interpolate_curve(points, t, 3, 3);
}

// A curve on the bicubic patch: a cubic interpolant of 400 points of S(u(t), v(t)).
NurbsCurve curve_on_patch(const NurbsSurface& patch) {
  std::vector<Eigen::Vector3d> points;
  std::vector<double> t;
  for (int k = 0; k <= 400; ++k) {
    const double a = k / 400.0;
    points.push_back(surface_point(patch, 0.1 + 1.8 * a, 0.5 + 0.35 * std::sin(5 * a)));
    t.push_back(a);
  }
  return interpolate_curve(points, t, 3, 3);
}

// The largest |S(c(s)) - edge(t(s))| at 1000 + 1 evenly spaced s, measured apart from the fit's checks.
double dense_distance(const TrimCurveFit& fit, const NurbsCurve& edge, double t0, double t1, const SurfaceAt& at) {
  double worst = 0.0;
  for (int k = 0; k <= 1000; ++k) {
    const double s = k / 1000.0;
    const Eigen::Vector3d uv = curve_point(fit.curve, s);
    worst = std::max(worst, (at(uv.head<2>()) - curve_point(edge, t0 + s * (t1 - t0))).norm());
  }
  return worst;
}

struct Case {
  const char* name;
  int most_points;  // the count measured when written, plus ~10 % (a regression in size fails)
};

// Fits, checks the contract, prints and bounds the control-point count.
TrimCurveFit fit_and_check(const NurbsCurve& edge, double t0, double t1, const Eigen::Vector2d& start_uv,
                           const LocateOnSurface& locate, const SurfaceAt& at, double tolerance, const Case& c) {
  const auto begin = std::chrono::steady_clock::now();
  const TrimCurveFit fit = fit_trim_curve(edge, t0, t1, start_uv, locate, at, tolerance);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count();
  validate(fit.curve, "fitted trim curve");
  EXPECT_EQ(fit.curve.dimension, 2);
  EXPECT_EQ(fit.curve.domain_start(), 0.0);
  EXPECT_EQ(fit.curve.domain_end(), 1.0);
  EXPECT_FALSE(fit.curve.is_rational());
  EXPECT_LE(fit.max_distance, tolerance);
  // Start exact: the caller's (u,v), bit for bit; end exact: the located (u,v) of edge(t1).
  EXPECT_EQ(curve_point(fit.curve, 0.0).head<2>(), start_uv);
  EXPECT_EQ(fit.curve.points.front().head<2>(), start_uv);
  EXPECT_EQ(curve_point(fit.curve, 1.0), fit.curve.points.back());
  const Eigen::Vector2d end = fit.curve.points.back().head<2>();
  EXPECT_LE((at(end) - curve_point(edge, t1)).norm(), tolerance);
  // The contract is checked points only; dense points may exceed it a little between them. Allowed
  // slack: 10 % (measured: the ellipse at 1e-6 reaches 1.06 tolerance, the others stay within it).
  const double dense = dense_distance(fit, edge, t0, t1, at);
  EXPECT_LE(dense, tolerance * 1.10) << c.name;
  EXPECT_LE(fit.curve.count(), c.most_points) << c.name;
  std::printf("[ fit      ] %-34s tol %.0e: %3d control points (degree %d), %4d checked, checked max %.3g tol, "
              "dense max %.3g tol, %.2f ms\n",
              c.name, tolerance, fit.curve.count(), fit.curve.degree(), fit.checked_points,
              fit.max_distance / tolerance, dense / tolerance, ms);
  return fit;
}

}  // namespace

TEST(FitTrimCurve, ObliqueEllipseOnCylinderAcrossTheSeam) {
  const CylinderFace face;
  const NurbsCurve edge = oblique_ellipse();
  const Eigen::Vector2d start = nearest_surface_parameter(face.surface, curve_point(edge, 0.0));
  for (auto [tolerance, most] : {std::pair{1e-4, 48}, std::pair{1e-6, 125}}) {
    const TrimCurveFit fit = fit_and_check(edge, 0.0, 4.0, start, face.locator(), face.evaluator(), tolerance,
                                           {"ellipse (cylinder cut at 26.6 deg)", most});
    // Once round: the end is the start one period on (the locator unwrapped the seam).
    EXPECT_NEAR(fit.curve.points.back().x(), start.x() + kPeriod, 1e-9);
  }
}

TEST(FitTrimCurve, HelixOnCylinder) {
  const CylinderFace face;
  const NurbsCurve edge = helix();
  // The edge itself is off the cylinder by interpolation error only, far below the tolerances.
  for (int k = 0; k <= 2000; ++k) EXPECT_NEAR(curve_point(edge, k / 2000.0).head<2>().norm(), 1.0, 1e-8);
  const Eigen::Vector2d start = nearest_surface_parameter(face.surface, curve_point(edge, 0.0));
  for (auto [tolerance, most] : {std::pair{1e-4, 70}, std::pair{1e-6, 128}})
    fit_and_check(edge, 0.0, 1.0, start, face.locator(), face.evaluator(), tolerance, {"helix 1.5 turns", most});
}

TEST(FitTrimCurve, CurveOnBicubicPatch) {
  const NurbsSurface patch = test::bicubic_patch();
  const NurbsCurve edge = curve_on_patch(patch);
  const LocateOnSurface locate = [&](const Eigen::Vector3d& p, const Eigen::Vector2d& previous) {
    return nearest_surface_parameter(patch, p, previous);
  };
  const SurfaceAt at = [&](const Eigen::Vector2d& uv) { return surface_point(patch, uv.x(), uv.y()); };
  const Eigen::Vector2d start(0.1, 0.5);
  for (auto [tolerance, most] : {std::pair{1e-4, 17}, std::pair{1e-6, 42}})
    fit_and_check(edge, 0.0, 1.0, start, locate, at, tolerance, {"sine path on bicubic patch", most});
}

TEST(FitTrimCurve, ReversedRangeRunsFromT0ToT1) {
  const CylinderFace face;
  const NurbsCurve edge = oblique_ellipse();
  const double t0 = 3.7, t1 = 0.4;
  const Eigen::Vector2d start = nearest_surface_parameter(face.surface, curve_point(edge, t0));
  const TrimCurveFit fit = fit_and_check(edge, t0, t1, start, face.locator(), face.evaluator(), 1e-5,
                                         {"ellipse 3.7 -> 0.4 (reversed)", 68});
  // From edge(3.7) back to edge(0.4): u falls across the seam to below 0 (unwrapped).
  const Eigen::Vector2d end = fit.curve.points.back().head<2>();
  EXPECT_LT(end.x(), start.x());
  EXPECT_LT((face.at(end) - curve_point(edge, t1)).norm(), 1e-9);
}

TEST(FitTrimCurve, StraightImagesGiveTwoPoints) {
  const CylinderFace face;
  // A ruling (a LINE edge) at 57 degrees, and a parallel (the circle at z = 1.2, which is the
  // surface's own u parametrisation): straight in (u,v), uniformly parametrised.
  NurbsCurve ruling;
  ruling.order = 2;
  ruling.knots = {0, 0, 1, 1};
  ruling.points = {{std::cos(1.0), std::sin(1.0), 2.7}, {std::cos(1.0), std::sin(1.0), 0.3}};
  NurbsCurve parallel = test::full_circle(1.0);
  for (Eigen::Vector3d& p : parallel.points) p.z() = 1.2;
  for (const auto& [edge, t0, t1] : {std::tuple{ruling, 0.0, 1.0}, std::tuple{parallel, 0.5, 3.5}}) {
    const Eigen::Vector2d start = nearest_surface_parameter(face.surface, curve_point(edge, t0));
    const TrimCurveFit fit = fit_and_check(edge, t0, t1, start, face.locator(), face.evaluator(), 1e-6,
                                           {"straight image", 2});
    EXPECT_EQ(fit.curve.degree(), 1);
    EXPECT_EQ(fit.curve.count(), 2);
  }
}

TEST(FitTrimCurve, RefusesAnEdgeOffTheSurface) {
  const CylinderFace face;
  const NurbsCurve edge = oblique_ellipse(1.01);  // radius 1.01: 0.01 off the cylinder
  const Eigen::Vector2d start = nearest_surface_parameter(face.surface, curve_point(edge, 0.0));
  try {
    fit_trim_curve(edge, 0.0, 4.0, start, face.locator(), face.evaluator(), 1e-4);
    FAIL() << "an edge 0.01 off its surface was fitted";
  } catch (const GeometryError& e) {
    EXPECT_EQ(std::string(e.what()),
              "trim curve fit: the edge does not lie on the surface: 0.01 from it at parameter 0 (tolerance 0.0001)");
  }
}

TEST(FitTrimCurve, RefusesAnImageThatJumps) {
  // A locator that unwraps the seam the wrong way half way round: the (u,v) samples jump by a period,
  // every point on the surface, but no curve through them follows the edge.
  const CylinderFace face;
  const NurbsCurve edge = oblique_ellipse();
  const LocateOnSurface jumping = [&](const Eigen::Vector3d& p, const Eigen::Vector2d& previous) {
    Eigen::Vector2d uv = face.locate(p, previous);
    if (p.y() < 0 && p.x() < 0 && uv.x() < 4.0) uv.x() += kPeriod;
    return uv;
  };
  const Eigen::Vector2d start = nearest_surface_parameter(face.surface, curve_point(edge, 0.0));
  try {
    fit_trim_curve(edge, 0.0, 4.0, start, jumping, face.evaluator(), 1e-4);
    FAIL() << "a jumping image was fitted";
  } catch (const GeometryError& e) {
    EXPECT_NE(std::string(e.what()).find("trim curve does not follow its edge within 0.0001 after "), std::string::npos)
        << e.what();
  }
}

TEST(FitTrimCurve, RefusesBadInput) {
  const CylinderFace face;
  const NurbsCurve edge = oblique_ellipse();
  const Eigen::Vector2d start = nearest_surface_parameter(face.surface, curve_point(edge, 0.0));
  EXPECT_THROW(fit_trim_curve(edge, 0.0, 4.0, {NAN, 0.5}, face.locator(), face.evaluator(), 1e-4), GeometryError);
  EXPECT_THROW(fit_trim_curve(edge, 0.0, NAN, start, face.locator(), face.evaluator(), 1e-4), GeometryError);
  EXPECT_THROW(fit_trim_curve(edge, 1.0, 1.0, start, face.locator(), face.evaluator(), 1e-4), GeometryError);
  EXPECT_THROW(fit_trim_curve(edge, 0.0, 4.5, start, face.locator(), face.evaluator(), 1e-4), GeometryError);
  EXPECT_THROW(fit_trim_curve(edge, 0.0, 4.0, start, face.locator(), face.evaluator(), 0.0), GeometryError);
  // A start (u,v) that is not the edge's start.
  EXPECT_THROW(fit_trim_curve(edge, 0.0, 4.0, start + Eigen::Vector2d(0.1, 0), face.locator(), face.evaluator(), 1e-4),
               GeometryError);
}

TEST(InterpolateCurve, PassesThroughItsPointsAndReproducesCubics) {
  // A cubic polynomial is reproduced exactly by cubic interpolation (its space holds it).
  std::vector<Eigen::Vector3d> points;
  std::vector<double> t;
  for (int k = 0; k <= 9; ++k) {
    const double a = std::pow(k / 9.0, 1.3);
    points.emplace_back(a, 2 * a * a * a - a, 0.0);
    t.push_back(a);
  }
  const NurbsCurve c = interpolate_curve(points, t, 3, 2);
  validate(c, "interpolant");
  for (size_t k = 0; k < points.size(); ++k) EXPECT_LT((curve_point(c, t[k]) - points[k]).norm(), 1e-13);
  for (double a = 0; a <= 1; a += 0.01) EXPECT_LT((curve_point(c, a) - Eigen::Vector3d(a, 2 * a * a * a - a, 0)).norm(), 1e-13);
  EXPECT_THROW(interpolate_curve(points, std::vector<double>(points.size(), 0.0), 3, 2), GeometryError);
  EXPECT_EQ(interpolate_curve({points[0], points[1]}, {0.0, 1.0}, 3, 2).degree(), 1);
}

// An edge that starts beyond a B-spline's domain (a file's edge off its face, as in KiCad's QFP fillets):
// its first samples are located on the domain's edge u = 0, the rest inside, and the interpolant of that
// kink overshoots to u < 0, across the face's boundary there. Given the domain, the curve stays in it.
TEST(FitTrimCurve, StaysInTheDomainItIsGiven) {
  NurbsSurface flat;  // (u, v) -> (u, v, 0) on [0, 1]^2
  flat.u_order = flat.v_order = 2;
  flat.u_count = flat.v_count = 2;
  flat.u_knots = flat.v_knots = {0, 0, 1, 1};
  flat.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  std::vector<Eigen::Vector3d> points;
  std::vector<double> t;
  for (int k = 0; k <= 40; ++k) {
    const double s = k / 40.0;
    points.emplace_back(-0.002 + 0.5 * s * s, 0.2 + 0.5 * s, 0.0);
    t.push_back(s);
  }
  const NurbsCurve edge = interpolate_curve(points, t, 3, 3);
  const LocateOnSurface locate = [&](const Eigen::Vector3d& p, const Eigen::Vector2d& previous) {
    return nearest_surface_parameter(flat, p, previous);
  };
  const SurfaceAt at = [&](const Eigen::Vector2d& uv) { return surface_point(flat, uv.x(), uv.y()); };
  const Eigen::Vector2d start = locate(curve_point(edge, 0.0), {0.0, 0.2});
  ASSERT_EQ(start.x(), 0.0);
  const double tolerance = 1e-6, off_surface = 0.01;
  const auto least_u = [](const NurbsCurve& c) {
    double u = 1.0;
    for (const auto& p : c.points) u = std::min(u, p.x());
    return u;
  };
  const TrimCurveFit free = fit_trim_curve(edge, 0.0, 1.0, start, locate, at, tolerance, off_surface);
  EXPECT_LT(least_u(free.curve), -1e-9) << "the unclamped interpolant should leave the domain here";
  const TrimCurveFit kept = fit_trim_curve(edge, 0.0, 1.0, start, locate, at, tolerance, off_surface,
                                           Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1)));
  EXPECT_GE(least_u(kept.curve), 0.0);
  EXPECT_LE(kept.max_distance, 4 * tolerance);
  EXPECT_EQ(kept.curve.points.front().head<2>(), start);
}
