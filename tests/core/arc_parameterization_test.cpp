// arc_parameterization and conic_curves: the unit arc lies on the circle at the angle arc_angle says,
// the parameter maps are inverses and equal the angle at knots; circle length by quadrature.
#include "core/arc_parameterization.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "analysis/eval/span_quadrature.hpp"
#include "core/conic_curves.hpp"
#include "core/geometry_error.hpp"

namespace cadnurbs {
namespace {

constexpr double kPi = std::numbers::pi;

// a - b reduced to (-pi, pi].
double angle_difference(double a, double b) { return std::remainder(a - b, 2 * kPi); }

TEST(ArcParameterization, FewestEqualSpansOfAtMostAQuarter) {
  EXPECT_EQ(arc_spans(0, kPi / 2).spans, 1);
  EXPECT_EQ(arc_spans(0.1, 0.1 + kPi / 2 + 1e-6).spans, 2);
  EXPECT_EQ(arc_spans(-1, -1 + kPi).spans, 2);
  EXPECT_EQ(arc_spans(-kPi, kPi).spans, 4);
  EXPECT_EQ(arc_spans(0, 2 * kPi + 5e-10).spans, 4);
  EXPECT_EQ(arc_spans(0, 1e-9).spans, 1);
}

TEST(ArcParameterization, UnitArcLiesOnTheCircleAtArcAngle) {
  std::mt19937 rng(37);
  std::uniform_real_distribution<double> start(-10, 10), sweep(1e-3, 2 * kPi), unit(0, 1);
  for (int trial = 0; trial < 50; ++trial) {
    const double a0 = start(rng);
    const ArcSpans arc = arc_spans(a0, a0 + (trial == 0 ? 2 * kPi : sweep(rng)));
    const NurbsCurve curve = unit_arc(arc);
    validate(curve, "unit arc");
    EXPECT_EQ(curve.dimension, 2);
    EXPECT_EQ(curve.count(), 2 * arc.spans + 1);
    EXPECT_EQ(curve.domain_start(), arc.start);
    EXPECT_EQ(curve.domain_end(), arc.end);
    for (int i = 0; i < 200; ++i) {
      const double s = arc.start + (arc.end - arc.start) * unit(rng);
      const Eigen::Vector3d p = curve_point(curve, s);
      EXPECT_NEAR(p.norm(), 1.0, 1e-14);
      EXPECT_EQ(p.z(), 0.0);
      const double a = arc_angle(arc, s);
      EXPECT_NEAR(angle_difference(std::atan2(p.y(), p.x()), a), 0.0, 1e-13);
      EXPECT_NEAR(arc_parameter(arc, a), s, 1e-12 * (1 + std::abs(s)));
      const double angle = arc.start + (arc.end - arc.start) * unit(rng);
      EXPECT_NEAR(arc_angle(arc, arc_parameter(arc, angle)), angle, 1e-12 * (1 + std::abs(angle)));
    }
  }
}

TEST(ArcParameterization, ParameterEqualsAngleAtEveryKnot) {
  for (const auto& [a0, a1] :
       {std::pair{0.0, 2 * kPi}, {-0.3, 2.9}, {1.0, 1.2}, {-kPi, kPi}, {5.0, 5.0 + 3 * kPi / 2}}) {
    const ArcSpans arc = arc_spans(a0, a1);
    const NurbsCurve curve = unit_arc(arc);
    for (double knot : curve.knots) {
      EXPECT_EQ(arc_parameter(arc, knot), knot);
      EXPECT_EQ(arc_angle(arc, knot), knot);
      const Eigen::Vector3d p = curve_point(curve, knot);
      EXPECT_NEAR(p.x(), std::cos(knot), 1e-15);
      EXPECT_NEAR(p.y(), std::sin(knot), 1e-15);
    }
  }
}

TEST(ArcParameterization, MapsAreMonotoneAndClampOvershoot) {
  const ArcSpans arc = arc_spans(-2, 3);
  double previous = -1e300;
  for (int i = 0; i <= 10000; ++i) {
    const double s = arc_parameter(arc, -2 + 5.0 * i / 10000);
    EXPECT_GE(s, previous);
    previous = s;
  }
  EXPECT_EQ(arc_parameter(arc, -2 - 1e-13), -2.0);
  EXPECT_EQ(arc_parameter(arc, 3 + 1e-13), 3.0);
  EXPECT_EQ(arc_angle(arc, 3.5), 3.0);
}

TEST(ArcParameterization, FullCircleLengthByQuadrature) {
  const double r = 2.5;
  AxisFrame frame;
  frame.origin = {1, 2, 3};
  const NurbsCurve circle = circle_arc(frame, r, 0.7, 0.7 + 2 * kPi);
  validate(circle, "circle");
  EXPECT_EQ(circle.points.front(), circle.points.back());
  const QuadratureRule& rule = gauss_legendre(20);
  double length = 0;
  for (int k = 0; k < 4; ++k) {  // span by span: the integrand is smooth inside each
    const double k0 = circle.knots[2 + 2 * k], k1 = circle.knots[4 + 2 * k];
    for (size_t i = 0; i < rule.nodes.size(); ++i)
      length += rule.weights[i] * (k1 - k0) * curve_derivatives(circle, k0 + rule.nodes[i] * (k1 - k0), 1)[1].norm();
  }
  EXPECT_NEAR(length, 2 * kPi * r, 1e-12 * r);
}

TEST(ConicCurves, CircleEllipseAndLineFollowTheirFormulas) {
  const AxisFrame frame = axis_frame({1, -1, 2}, Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(0, 0, 1), "frame");
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0, 1);
  const double a0 = -0.4, a1 = 4.1;
  const ArcSpans arc = arc_spans(a0, a1);
  const NurbsCurve circle = circle_arc(frame, 3, a0, a1);
  const NurbsCurve ellipse = ellipse_arc(frame, 3, 0.5, a0, a1);
  const NurbsCurve circle_2d = circle_arc_2d({2, -3}, 0.25, a0, a1);
  const NurbsCurve clockwise = circle_arc_2d({2, -3}, 0.25, a1, a0);
  const NurbsCurve line = line_segment({0, 0, 1}, {2, 4, 1}, -1, 3);
  for (const NurbsCurve* c : {&circle, &ellipse, &circle_2d, &clockwise, &line}) validate(*c, "conic");
  EXPECT_EQ(circle_2d.dimension, 2);
  EXPECT_EQ(clockwise.domain_start(), a0);
  EXPECT_EQ(clockwise.domain_end(), a1);
  for (int i = 0; i < 200; ++i) {
    const double a = a0 + (a1 - a0) * unit(rng), s = arc_parameter(arc, a);
    const Eigen::Vector3d in_plane = std::cos(a) * frame.x + std::sin(a) * frame.y;
    EXPECT_LT((curve_point(circle, s) - (frame.origin + 3 * in_plane)).norm(), 1e-14 * 3);
    const Eigen::Vector3d on_ellipse = frame.origin + 3 * std::cos(a) * frame.x + 0.5 * std::sin(a) * frame.y;
    EXPECT_LT((curve_point(ellipse, s) - on_ellipse).norm(), 1e-14 * 3);
    const Eigen::Vector3d on_2d(2 + 0.25 * std::cos(a), -3 + 0.25 * std::sin(a), 0);
    EXPECT_LT((curve_point(circle_2d, s) - on_2d).norm(), 1e-14);
    EXPECT_LT((curve_point(clockwise, a0 + a1 - s) - on_2d).norm(), 1e-14);
    const double t = -1 + 4 * unit(rng);
    EXPECT_LT((curve_point(line, t) - Eigen::Vector3d(0.5 * (t + 1), t + 1, 1)).norm(), 1e-14);
  }
  EXPECT_LT((curve_point(clockwise, a0) - Eigen::Vector3d(2 + 0.25 * std::cos(a1), -3 + 0.25 * std::sin(a1), 0)).norm(),
            1e-15);
}

TEST(ConicCurves, Refusals) {
  auto reason = [](auto make) {
    try {
      make();
    } catch (const GeometryError& e) {
      return std::string(e.what());
    }
    return std::string("no refusal");
  };
  EXPECT_NE(reason([] { arc_spans(1, 1); }).find("arc: its end angle"), std::string::npos);
  EXPECT_NE(reason([] { arc_spans(0, 2 * kPi + 1e-8); }).find("exceeds 2 pi"), std::string::npos);
  EXPECT_NE(reason([] { circle_arc(AxisFrame{}, 0, 0, 1); }).find("circle: radius"), std::string::npos);
  EXPECT_NE(reason([] { ellipse_arc(AxisFrame{}, 1, -2, 0, 1); }).find("ellipse: radius"), std::string::npos);
  EXPECT_NE(reason([] { circle_arc_2d({0, 0}, 1, 0, 7); }).find("circle: its sweep"), std::string::npos);
  EXPECT_NE(reason([] { circle_arc_2d({0, 0}, 1, 2, 2); }).find("equal"), std::string::npos);
  EXPECT_NE(reason([] { line_segment({0, 0, 0}, {1, 0, 0}, 1, 1); }).find("line segment"), std::string::npos);
}

}  // namespace
}  // namespace cadnurbs
