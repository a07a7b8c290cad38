#include "analysis_shapes.hpp"

#include <cmath>

namespace cadnurbs::test {

namespace {

const double kW = std::sqrt(0.5);

// The unit full circle's 9 control points (x, y) and weights, knots {0,0,0,1,1,2,2,3,3,4,4,4}.
const double kCircleX[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1};
const double kCircleY[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
const double kCircleW[9] = {1, kW, 1, kW, 1, kW, 1, kW, 1};

}  // namespace

NurbsCurve circle_2d(const Eigen::Vector2d& c, double r) {
  NurbsCurve out;
  out.dimension = 2;
  out.order = 3;
  out.knots = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
  for (int i = 0; i < 9; ++i) {
    out.points.emplace_back(c.x() + r * kCircleX[i], c.y() + r * kCircleY[i], 0.0);
    out.weights.push_back(kCircleW[i]);
  }
  return out;
}

TrimmedSurface quarter_cylinder(double radius, double height) {
  TrimmedSurface t;
  NurbsSurface& s = t.surface;
  s.u_order = 3, s.v_order = 2, s.u_count = 3, s.v_count = 2;
  s.u_knots = {0, 0, 0, 1, 1, 1};
  s.v_knots = {0, 0, 1, 1};
  const double x[3] = {1, 1, 0}, y[3] = {0, 1, 1}, w[3] = {1, kW, 1};
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      s.points.emplace_back(radius * x[i], radius * y[i], j * height);
      s.weights.push_back(w[i]);
    }
  return t;
}

double distance_to_cylinder(const Eigen::Vector3d& p, double radius) { return std::abs(p.head<2>().norm() - radius); }

TrimmedSurface sphere(double radius) {
  TrimmedSurface t;
  NurbsSurface& s = t.surface;
  s.u_order = 3, s.v_order = 3, s.u_count = 9, s.v_count = 5;
  s.u_knots = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
  s.v_knots = {0, 0, 0, 1, 1, 2, 2, 2};
  // Meridian in (rho, z), south to north.
  const double rho[5] = {0, 1, 1, 1, 0}, z[5] = {-1, -1, 0, 1, 1}, wv[5] = {1, kW, 1, kW, 1};
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 9; ++i) {
      s.points.emplace_back(radius * rho[j] * kCircleX[i], radius * rho[j] * kCircleY[i], radius * z[j]);
      s.weights.push_back(kCircleW[i] * wv[j]);
    }
  return t;
}

double distance_to_sphere(const Eigen::Vector3d& p, double radius) { return std::abs(p.norm() - radius); }

TrimmedSurface sphere_with_edges(double radius, int first) {
  TrimmedSurface t = sphere(radius);
  const Eigen::Vector2d a(0, 0), b(4, 0), c(4, 2), d(0, 2);
  TrimLoop loop;
  for (const auto& [p, q] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, d}, std::pair{d, a}})
    loop.segments.emplace_back(Polyline2D{{p, q}});
  loop.edges = {{first, false}, {first + 1, false}, {first + 2, false}, {first + 1, true}};
  t.loops.push_back(loop);
  return t;
}

TrimmedSurface torus_patch(double major, double minor) {
  TrimmedSurface t;
  NurbsSurface& s = t.surface;
  s.u_order = 3, s.v_order = 3, s.u_count = 3, s.v_count = 3;
  s.u_knots = s.v_knots = {0, 0, 0, 1, 1, 1};
  const double x[3] = {1, 1, 0}, y[3] = {0, 1, 1}, w[3] = {1, kW, 1};
  // Tube quarter from the outer equator up to the top: (rho, z).
  const double rho[3] = {major + minor, major + minor, major}, z[3] = {0, minor, minor};
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      s.points.emplace_back(rho[j] * x[i], rho[j] * y[i], z[j]);
      s.weights.push_back(w[i] * w[j]);
    }
  return t;
}

double distance_to_torus(const Eigen::Vector3d& p, double major, double minor) {
  const double q = p.head<2>().norm() - major;
  return std::abs(std::hypot(q, p.z()) - minor);
}

TrimmedSurface trimmed_square(double size, double outer, double inner) {
  TrimmedSurface t;
  NurbsSurface& s = t.surface;
  s.u_order = s.v_order = 2, s.u_count = s.v_count = 2;
  s.u_knots = s.v_knots = {0, 0, 1, 1};
  s.points = {{0, 0, 0}, {size, 0, 0}, {0, size, 0}, {size, size, 0}};
  TrimLoop out_loop, hole;
  out_loop.segments.emplace_back(circle_2d({0.5, 0.5}, outer));
  hole.segments.emplace_back(reversed(circle_2d({0.5, 0.5}, inner)));
  t.loops = {out_loop, hole};
  return t;
}

}  // namespace cadnurbs::test
