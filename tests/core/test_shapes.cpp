#include "test_shapes.hpp"

#include <cmath>

namespace cadnurbs::test {

NurbsCurve quarter_circle(double radius) {
  NurbsCurve c;
  c.dimension = 3;
  c.order = 3;
  c.knots = {0, 0, 0, 1, 1, 1};
  c.points = {{radius, 0, 0}, {radius, radius, 0}, {0, radius, 0}};
  c.weights = {1, std::sqrt(0.5), 1};
  return c;
}

NurbsCurve full_circle(double radius) {
  NurbsCurve c;
  c.order = 3;
  c.knots = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
  const double r = radius, w = std::sqrt(0.5);
  c.points = {{r, 0, 0}, {r, r, 0}, {0, r, 0}, {-r, r, 0}, {-r, 0, 0}, {-r, -r, 0}, {0, -r, 0}, {r, -r, 0}, {r, 0, 0}};
  c.weights = {1, w, 1, w, 1, w, 1, w, 1};
  return c;
}

NurbsSurface quarter_cylinder(double radius, double height) {
  const NurbsCurve arc = quarter_circle(radius);
  NurbsSurface s;
  s.u_order = 3;
  s.v_order = 2;
  s.u_count = 3;
  s.v_count = 2;
  s.u_knots = arc.knots;
  s.v_knots = {0, 0, 1, 1};
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      s.points.push_back(arc.points[i] + Eigen::Vector3d(0, 0, j * height));
      s.weights.push_back(arc.weights[i]);
    }
  return s;
}

}  // namespace cadnurbs::test
