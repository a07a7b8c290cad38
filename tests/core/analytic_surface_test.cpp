// analytic_surface: every surface's NURBS against its closed form at 200 random natural points, the
// parameter maps as inverses, point inversion back to the natural parameters, the sphere's and torus's
// areas by Gauss-Legendre over the NURBS, exact knots, refusals.
#include "core/analytic_surface.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "analysis/eval/span_quadrature.hpp"
#include "core/conic_curves.hpp"
#include "core/geometry_error.hpp"
#include "core/knot_vector.hpp"

namespace cadnurbs {
namespace {

constexpr double kPi = std::numbers::pi;

AxisFrame tilted_frame() {
  return axis_frame({0.5, -1, 2}, Eigen::Vector3d(0.3, -0.4, 1), Eigen::Vector3d(1, 0.2, 0), "frame");
}

// A non-planar rational quadratic profile well away from the axis below, over [0, 3].
NurbsCurve twisted_profile() {
  NurbsCurve c;
  c.order = 3;
  c.knots = {0, 0, 0, 1, 2, 2, 3, 3, 3};
  c.points = {{3, 0, 0}, {4, 1, 0.5}, {3.5, 2, 1}, {4.5, 3, 0.2}, {3, 4, -0.5}, {3.2, 5, 0}};
  c.weights = {1, 0.8, 1.3, 1, 0.7, 1};
  return c;
}

NurbsCurve cubic_profile() {
  NurbsCurve c;
  c.order = 4;
  c.knots = {-1, -1, -1, -1, 0, 0.5, 2, 2, 2, 2};
  c.points = {{0, 0, 0}, {1, 2, 0}, {2, -1, 0.5}, {3, 1, 0}, {4, 0, 1}, {5, 2, 0}};
  return c;
}

struct Case {
  std::string name;
  AnalyticSurface surface;
  NaturalBox box;
  double size;
};

std::vector<Case> cases() {
  const AxisFrame f = tilted_frame();
  return {
      {"plane", PlaneSurface{f}, {-3, 2, 1, 4}, 5},
      {"cylinder", CylinderSurface{f, 2}, {0.3, 0.3 + 2 * kPi, -1, 3}, 4},
      {"cylinder part", CylinderSurface{f, 2}, {-2, 1, -1, 3}, 4},
      {"cone", ConeSurface{f, 1, 0.4}, {-1, 2, -1, 2}, 3},
      {"cone through its apex", ConeSurface{f, 1, 0.4}, {-kPi, kPi, -4, 1}, 4},
      {"cone of radius 0", ConeSurface{f, 0, 1.2}, {0, 2 * kPi, 0, 2}, 6},
      {"sphere", SphereSurface{f, 1.5}, {-kPi, kPi, -kPi / 2, kPi / 2}, 1.5},
      {"sphere part", SphereSurface{f, 1.5}, {0.5, 2, -0.3, 1.2}, 1.5},
      {"torus", TorusSurface{f, 3, 1}, {0, 2 * kPi, 0, 2 * kPi}, 4},
      {"torus part", TorusSurface{f, 3, 1}, {-1, 0.5, 2, 4.5}, 4},
      {"spindle torus", TorusSurface{f, 1, 1.5}, {-kPi, kPi, -kPi, kPi}, 2.5},
      {"revolution", RevolutionSurface{twisted_profile(), {1, 0, 0}, {0, 1, 1}}, {0.2, 5.2, 0.4, 2.7}, 8},
      {"revolution whole", RevolutionSurface{twisted_profile(), {1, 0, 0}, {0, 1, 1}}, {-kPi, kPi, 0, 3}, 8},
      {"extrusion", ExtrusionSurface{cubic_profile(), {0.3, 0.2, 2}}, {-0.7, 1.5, -1, 2}, 6},
  };
}

// The distance of a natural point from the surface's axis, where its angle is ill-conditioned.
double axis_distance(const Case& c, const Eigen::Vector2d& x) {
  return std::visit(
      [&](const auto& s) -> double {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, ConeSurface>)
          return std::abs(s.radius + x.y() * std::tan(s.semi_angle));
        else if constexpr (std::is_same_v<S, SphereSurface>)
          return s.radius * std::cos(x.y());
        else if constexpr (std::is_same_v<S, TorusSurface>)
          return std::abs(s.major_radius + s.minor_radius * std::cos(x.y()));
        else
          return c.size;
      },
      c.surface);
}

Eigen::Vector2d random_in(const NaturalBox& box, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0, 1);
  return {box.u0 + (box.u1 - box.u0) * unit(rng), box.v0 + (box.v1 - box.v0) * unit(rng)};
}

TEST(AnalyticSurface, NurbsMatchesTheClosedFormAndMapsInvert) {
  std::mt19937 rng(37);
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const SurfaceConversion conversion = analytic_to_nurbs(c.surface, c.box);
    validate(conversion.surface, c.name);
    const std::array<bool, 2> angular = angular_directions(c.surface);
    for (int i = 0; i < 200; ++i) {
      const Eigen::Vector2d x = random_in(c.box, rng);
      const Eigen::Vector2d s = conversion.to_nurbs(x);
      const Eigen::Vector3d p = natural_point(c.surface, x);
      EXPECT_LT((surface_point(conversion.surface, s.x(), s.y()) - p).norm(), 1e-12 * c.size) << x.transpose();
      EXPECT_LT((conversion.to_natural(s) - x).norm(), 1e-12 * (1 + x.norm()));
      // Inverted without a hint: angles in (-pi, pi], equal modulo 2 pi; with a hint: equal.
      const double angle_tolerance = 1e-12 * c.size / axis_distance(c, x);
      const Eigen::Vector2d free = natural_inverse(c.surface, p);
      const Eigen::Vector2d hinted = natural_inverse(c.surface, p, Eigen::Vector2d(x + Eigen::Vector2d(0.4, -0.3)));
      for (int d = 0; d < 2; ++d) {
        const double tolerance = angular[d] ? angle_tolerance : 1e-11 * (1 + std::abs(x[d]));
        if (angular[d]) {
          EXPECT_GT(free[d], -kPi);
          EXPECT_LE(free[d], kPi);
          EXPECT_NEAR(std::remainder(free[d] - x[d], 2 * kPi), 0, tolerance) << c.name << " " << x.transpose();
        } else {
          EXPECT_NEAR(free[d], x[d], tolerance) << x.transpose();
        }
        EXPECT_NEAR(hinted[d], x[d], tolerance) << x.transpose();
      }
    }
  }
}

TEST(AnalyticSurface, ArcKnotsAreTheAngles) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const SurfaceConversion conversion = analytic_to_nurbs(c.surface, c.box);
    for (int d = 0; d < 2; ++d) {
      if (!conversion.arcs[d]) continue;
      const std::vector<double>& knots = d == 0 ? conversion.surface.u_knots : conversion.surface.v_knots;
      for (double knot : knots) {
        Eigen::Vector2d at(c.box.u0, c.box.v0);
        at[d] = knot;
        EXPECT_EQ(conversion.to_natural(at)[d], knot);
        EXPECT_EQ(conversion.to_nurbs(at)[d], knot);
      }
    }
  }
  // The non-angular directions keep their natural parameters: the box's ends are the domain's.
  const SurfaceConversion plane = analytic_to_nurbs(PlaneSurface{}, {-3, 2, 1, 4});
  EXPECT_EQ(plane.surface.u_start(), -3);
  EXPECT_EQ(plane.surface.v_end(), 4);
  EXPECT_FALSE(plane.arcs[0] || plane.arcs[1]);
  const SurfaceConversion sphere = analytic_to_nurbs(SphereSurface{{}, 1}, {0, kPi, -kPi / 2, kPi / 2});
  EXPECT_TRUE(sphere.arcs[0] && sphere.arcs[1]);
  EXPECT_EQ(angular_directions(SphereSurface{{}, 1}), (std::array<bool, 2>{true, false}));
}

// The area of a NURBS surface: Gauss-Legendre over each Bézier patch of |Su x Sv|.
double area(const NurbsSurface& s) {
  const QuadratureRule& rule = gauss_legendre(16);
  const std::vector<double> us = domain_breaks(s.u_knots, s.u_order, s.u_count);
  const std::vector<double> vs = domain_breaks(s.v_knots, s.v_order, s.v_count);
  double total = 0;
  for (size_t i = 0; i + 1 < us.size(); ++i)
    for (size_t j = 0; j + 1 < vs.size(); ++j)
      for (size_t a = 0; a < rule.nodes.size(); ++a)
        for (size_t b = 0; b < rule.nodes.size(); ++b) {
          const double u = us[i] + (us[i + 1] - us[i]) * rule.nodes[a];
          const double v = vs[j] + (vs[j + 1] - vs[j]) * rule.nodes[b];
          const auto d = surface_derivatives(s, u, v, 1);
          total += rule.weights[a] * rule.weights[b] * (us[i + 1] - us[i]) * (vs[j + 1] - vs[j]) *
                   d[1][0].cross(d[0][1]).norm();
        }
  return total;
}

TEST(AnalyticSurface, SphereAndTorusAreasByQuadrature) {
  const AxisFrame f = tilted_frame();
  const double r = 1.5;
  EXPECT_NEAR(area(analytic_to_nurbs(SphereSurface{f, r}, {-kPi, kPi, -kPi / 2, kPi / 2}).surface), 4 * kPi * r * r,
              1e-11 * r * r);
  const double big = 3, small = 0.75;
  EXPECT_NEAR(area(analytic_to_nurbs(TorusSurface{f, big, small}, {0, 2 * kPi, -kPi, kPi}).surface),
              4 * kPi * kPi * big * small, 1e-11 * big * small);
  // A zone of the sphere: 2 pi r h, Archimedes' hat-box.
  EXPECT_NEAR(area(analytic_to_nurbs(SphereSurface{f, r}, {0, 2 * kPi, -0.2, 0.9}).surface),
              2 * kPi * r * r * (std::sin(0.9) - std::sin(-0.2)), 1e-11 * r * r);
}

TEST(AnalyticSurface, AxisPointsTakeTheHintsAngle) {
  const AxisFrame f = tilted_frame();
  const SphereSurface sphere{f, 2};
  const Eigen::Vector3d pole = f.origin + 2 * f.z;
  EXPECT_EQ(natural_inverse(sphere, pole), Eigen::Vector2d(0, kPi / 2));
  EXPECT_EQ(natural_inverse(sphere, pole, Eigen::Vector2d(2.5, 1.4)).x(), 2.5);
  const ConeSurface cone{f, 1, 0.4};
  const Eigen::Vector3d apex = natural_point(cone, {0.7, -1 / std::tan(0.4)});
  const Eigen::Vector2d at_apex = natural_inverse(cone, apex, Eigen::Vector2d(-3, 0));
  EXPECT_EQ(at_apex.x(), -3);
  EXPECT_NEAR(at_apex.y(), -1 / std::tan(0.4), 1e-14);
  // A hint several turns away unwraps the angle to within pi of it.
  const CylinderSurface cylinder{f, 1};
  EXPECT_NEAR(natural_inverse(cylinder, natural_point(cylinder, {0.5, 1}), Eigen::Vector2d(0.5 + 6 * kPi + 3, 0)).x(),
              0.5 + 6 * kPi, 1e-12);
  EXPECT_NEAR(natural_inverse(cylinder, natural_point(cylinder, {kPi, 1})).x(), kPi, 1e-15);
}

// Off the surface along the normal: the inverse finds a foot no farther than the point it started from,
// where the offset is orthogonal to the surface (central differences of natural_point).
TEST(AnalyticSurface, PointsOffTheSurfaceFindTheirFoot) {
  std::mt19937 rng(11);
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const SurfaceConversion conversion = analytic_to_nurbs(c.surface, c.box);
    for (int i = 0; i < 20; ++i) {
      const Eigen::Vector2d x = random_in(c.box, rng);
      const Eigen::Vector2d s = conversion.to_nurbs(x);
      const Eigen::Vector3d normal = surface_normal(conversion.surface, s.x(), s.y());
      const double offset = 0.02 * std::min(c.size, axis_distance(c, x));
      const Eigen::Vector3d off = natural_point(c.surface, x) + offset * normal;
      const Eigen::Vector2d y = natural_inverse(c.surface, off, x);
      const Eigen::Vector3d gap = off - natural_point(c.surface, y);
      EXPECT_LE(gap.norm(), offset + 1e-12 * c.size) << x.transpose();
      const double h = 1e-6;
      for (int d = 0; d < 2; ++d) {
        const Eigen::Vector2d step = h * Eigen::Vector2d::Unit(d);
        const Eigen::Vector3d tangent =
            (natural_point(c.surface, y + step) - natural_point(c.surface, y - step)) / (2 * h);
        EXPECT_LT(std::abs(gap.dot(tangent)), 1e-7 * c.size * tangent.norm()) << x.transpose();
      }
    }
  }
}

TEST(AnalyticSurface, Refusals) {
  auto message = [](const AnalyticSurface& s, NaturalBox box) {
    try {
      analytic_to_nurbs(s, box);
    } catch (const GeometryError& e) {
      return std::string(e.what());
    }
    return std::string("no refusal");
  };
  const AxisFrame f;
  EXPECT_EQ(message(CylinderSurface{f, 0}, {0, 1, 0, 1}), "cylindrical surface: radius 0.000000 is not positive");
  EXPECT_EQ(message(SphereSurface{f, -1}, {0, 1, 0, 1}), "spherical surface: radius -1.000000 is not positive");
  EXPECT_EQ(message(TorusSurface{f, 0, 1}, {0, 1, 0, 1}), "toroidal surface: major radius 0.000000 is not positive");
  EXPECT_EQ(message(ConeSurface{f, -1, 0.3}, {0, 1, 0, 1}), "conical surface: radius -1.000000 is negative");
  EXPECT_EQ(message(ConeSurface{f, 1, kPi / 2}, {0, 1, 0, 1}).find("conical surface: semi-angle"), 0u);
  EXPECT_EQ(message(PlaneSurface{f}, {0, 1, 2, 2}),
            "plane: its parameter box [0.000000, 1.000000] x [2.000000, 2.000000] is empty");
  EXPECT_NE(
      message(CylinderSurface{f, 1}, {0, 2 * kPi + 1e-8, 0, 1}).find("cylindrical surface: angular range: its sweep"),
      std::string::npos);
  EXPECT_NE(message(TorusSurface{f, 2, 1}, {0, 1, 0, 7}).find("exceeds 2 pi"), std::string::npos);
  EXPECT_NE(message(SphereSurface{f, 1}, {0, 1, -2, 0}).find("spherical surface: its latitude range"),
            std::string::npos);
  EXPECT_NE(message(RevolutionSurface{twisted_profile(), {0, 0, 0}, {0, 0, 0}}, {0, 1, 0, 1}).find("direction is zero"),
            std::string::npos);
  EXPECT_NE(message(ExtrusionSurface{cubic_profile(), {0, 0, 1}}, {-2, 1, 0, 1}).find("leaves the profile's domain"),
            std::string::npos);
  EXPECT_NE(message(PlaneSurface{f}, {0, NAN, 0, 1}).find("not finite"), std::string::npos);
  // Allowed: a spindle torus, a sphere's b a hair past the pole (clamped), a full turn plus rounding.
  EXPECT_EQ(message(TorusSurface{f, 1, 2}, {0, 1, 0, 1}), "no refusal");
  EXPECT_EQ(message(SphereSurface{f, 1}, {0, 2 * kPi + 1e-10, -kPi / 2 - 1e-10, kPi / 2}), "no refusal");
}

// A profile through the axis (KiCad's axial inductors: an end cap revolved from a 213 mm arc): points of
// the cap near the axis are found on their own sheet, not on the profile's mirror image across the axis
// 0.4 mm away.
TEST(AnalyticSurface, ProfileThroughTheAxisFindsTheRightSheet) {
  const AxisFrame profile_frame = axis_frame({214.00961664559, 0, -19.23194261324}, Eigen::Vector3d(0, -1, 0),
                                             Eigen::Vector3d(1, 0, 0), "profile");
  const RevolutionSurface cap{circle_arc(profile_frame, 213.27166950571, -kPi, kPi), {1.78, 0, 1.45}, {1, 0, 0}};
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  int tried = 0;
  const double start = cap.profile.domain_start(), end = cap.profile.domain_end();
  for (int i = 0; i <= 200000; ++i) {
    const double t = start + (end - start) * i / 200000;
    const Eigen::Vector3d q = curve_point(cap.profile, t) - cap.axis_point;
    const double rho = std::hypot(q.y(), q.z());
    if (q.x() > 10 || rho < 0.3 || rho > 1.4) continue;  // the cap: 0.375 to 1.35 mm from the axis
    ++tried;
    const Eigen::Vector3d p = natural_point(cap, {angle(rng), t});
    const Eigen::Vector3d found = natural_point(cap, natural_inverse(cap, p));
    EXPECT_LT((found - p).norm(), 1e-9 * 214) << "profile parameter " << t;
  }
  EXPECT_GT(tried, 20);
}

}  // namespace
}  // namespace cadnurbs
