#pragma once
// A tensor-product NURBS surface. Control points in VRML order: index i + j * u_count (u fastest).
#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace cadnurbs {

struct NurbsSurface {
  int u_order = 2, v_order = 2;
  int u_count = 0, v_count = 0;
  std::vector<double> u_knots, v_knots;   // u_count + u_order and v_count + v_order values
  std::vector<Eigen::Vector3d> points;     // u_count * v_count Euclidean points
  std::vector<double> weights;            // empty (polynomial) or one > 0 per point

  int index(int i, int j) const { return i + j * u_count; }
  const Eigen::Vector3d& point(int i, int j) const { return points[index(i, j)]; }
  bool is_rational() const { return !weights.empty(); }
  double weight(int i, int j) const { return weights.empty() ? 1.0 : weights[index(i, j)]; }
  double u_start() const { return u_knots[u_order - 1]; }
  double u_end() const { return u_knots[u_count]; }
  double v_start() const { return v_knots[v_order - 1]; }
  double v_end() const { return v_knots[v_count]; }
};

// Throws GeometryError(entity, reason) unless the surface is valid (orders, counts, knots, weights,
// finite points, points.size() == u_count * v_count).
void validate(const NurbsSurface& surface, const std::string& entity);

// Point at (u, v), clamped to the domain.
Eigen::Vector3d surface_point(const NurbsSurface& surface, double u, double v);

// d[k][l] = d^{k+l} S / du^k dv^l at (u, v) for k + l <= max_derivative (Piegl & Tiller A3.6, A4.4).
std::vector<std::vector<Eigen::Vector3d>> surface_derivatives(const NurbsSurface& surface, double u, double v,
                                                              int max_derivative);

// L = bound on |∂S/∂u| and |∂S/∂v| from the control net: max over rows and columns of
// (k-1)·|P_{i+1} - P_i| / (t_{i+k} - t_{i+1}), times (w_max/w_min)^2 for rational surfaces.
double surface_derivative_bound(const NurbsSurface& surface);

// A distance in (u,v) that moves the surface point by at most τ/10 (τ = coordinate_tolerance): τ/(10·L),
// at most 1/1000 of the domain's size. The precision of trimming curves written within τ: finer than
// the control points', because a trimmed region's area moves with its whole boundary (a boundary moved
// by τ/2 changes a thin part's area by more than a millionth; τ/10 costs a few per cent of a file).
double trim_parameter_tolerance(const NurbsSurface& surface, double coordinate_tolerance);

// Unit normal Su x Sv at (u, v); near a degenerate point (Su x Sv ~ 0) it steps a little into the
// domain. Returns zero only if the surface is degenerate around (u, v).
Eigen::Vector3d surface_normal(const NurbsSurface& surface, double u, double v);

}  // namespace cadnurbs
