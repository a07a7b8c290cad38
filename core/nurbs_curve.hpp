#pragma once
// A NURBS curve in 2D or 3D. 2D curves (trimming curves in a surface's (u,v) domain) keep z = 0.
#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace cadnurbs {

struct NurbsCurve {
  int dimension = 3;                  // 2 or 3
  int order = 2;                      // degree + 1, >= 2
  std::vector<double> knots;          // points.size() + order values, non-decreasing
  std::vector<Eigen::Vector3d> points;  // Euclidean control points
  std::vector<double> weights;        // empty (polynomial) or one positive weight per point

  int degree() const { return order - 1; }
  int count() const { return static_cast<int>(points.size()); }
  bool is_rational() const { return !weights.empty(); }
  double weight(int i) const { return weights.empty() ? 1.0 : weights[i]; }
  double domain_start() const { return knots[order - 1]; }
  double domain_end() const { return knots[points.size()]; }
};

// Throws GeometryError("<entity>", reason) unless `curve` is valid: dimension 2 or 3, order >= 2,
// enough control points, a valid knot vector, weights empty or one > 0 per point, finite coordinates,
// z = 0 for 2D curves.
void validate(const NurbsCurve& curve, const std::string& entity);

// Point at t (clamped to the domain).
Eigen::Vector3d curve_point(const NurbsCurve& curve, double t);

// ders[k] = k-th derivative at t for k = 0..max_derivative (Piegl & Tiller A3.2 and A4.2).
std::vector<Eigen::Vector3d> curve_derivatives(const NurbsCurve& curve, double t, int max_derivative);

// The same curve traversed the other way (knots mirrored in the domain).
NurbsCurve reversed(const NurbsCurve& curve);

}  // namespace cadnurbs
