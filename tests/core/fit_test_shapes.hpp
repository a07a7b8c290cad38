#pragma once
// Surfaces and curves on them for the point inversion and trim fitting tests.
#include <cmath>
#include <vector>

#include "core/nurbs_curve.hpp"
#include "core/nurbs_surface.hpp"
#include "test_shapes.hpp"

namespace cadnurbs::test {

// The whole cylinder of `radius` about Z from z = 0 to `height`: u in [0, 4] along the 9-point circle
// (seam at angle 0, u = k at angle k * 90 degrees), v in [0, 1] along Z. Rational quadratic x linear.
inline NurbsSurface full_cylinder(double radius, double height) {
  const NurbsCurve circle = full_circle(radius);
  NurbsSurface s;
  s.u_order = 3, s.v_order = 2;
  s.u_count = circle.count(), s.v_count = 2;
  s.u_knots = circle.knots;
  s.v_knots = {0, 0, 1, 1};
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < circle.count(); ++i) {
      s.points.push_back(circle.points[i] + Eigen::Vector3d(0, 0, j * height));
      s.weights.push_back(circle.weights[i]);
    }
  return s;
}

// A doubly curved bicubic patch over [0, 2] x [0, 1] with uneven knots (3 x 2 spans).
inline NurbsSurface bicubic_patch() {
  NurbsSurface s;
  s.u_order = s.v_order = 4;
  s.u_count = 6, s.v_count = 5;
  s.u_knots = {0, 0, 0, 0, 0.5, 1.3, 2, 2, 2, 2};
  s.v_knots = {0, 0, 0, 0, 0.4, 1, 1, 1, 1};
  for (int j = 0; j < s.v_count; ++j)
    for (int i = 0; i < s.u_count; ++i) {
      const double x = 0.8 * i, y = 0.7 * j;
      s.points.emplace_back(x + 0.1 * y, y, 0.6 * std::cos(0.9 * x) * std::sin(1.1 * y + 0.3) + 0.15 * x * y);
    }
  return s;
}

}  // namespace cadnurbs::test
