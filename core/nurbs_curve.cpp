#include "core/nurbs_curve.hpp"

#include <algorithm>
#include <cmath>

#include "core/geometry_error.hpp"
#include "core/knot_vector.hpp"
#include "core/rational_derivatives.hpp"

namespace cadnurbs {

void validate(const NurbsCurve& curve, const std::string& entity) {
  if (curve.dimension != 2 && curve.dimension != 3)
    throw GeometryError(entity, "dimension " + std::to_string(curve.dimension) + " is neither 2 nor 3");
  if (const std::string fault = knot_vector_fault(curve.knots, curve.order, curve.count()); !fault.empty())
    throw GeometryError(entity, fault);
  if (!curve.weights.empty() && curve.weights.size() != curve.points.size())
    throw GeometryError(entity, std::to_string(curve.weights.size()) + " weights for " +
                                    std::to_string(curve.points.size()) + " control points");
  for (size_t i = 0; i < curve.weights.size(); ++i)
    if (!(curve.weights[i] > 0.0) || !std::isfinite(curve.weights[i]))
      throw GeometryError(entity, "weight " + std::to_string(i) + " is " + std::to_string(curve.weights[i]) +
                                      "; weights must be positive");
  for (size_t i = 0; i < curve.points.size(); ++i) {
    if (!curve.points[i].allFinite())
      throw GeometryError(entity, "control point " + std::to_string(i) + " is not finite");
    if (curve.dimension == 2 && curve.points[i].z() != 0.0)
      throw GeometryError(entity, "control point " + std::to_string(i) + " of a 2D curve has z != 0");
  }
}

std::vector<Eigen::Vector3d> curve_derivatives(const NurbsCurve& curve, double t, int max_derivative) {
  const int span = find_knot_span(curve.knots, curve.order, curve.count(), t);
  const auto basis = basis_function_derivatives(curve.knots, curve.order, span, t, max_derivative);
  // Derivatives of the homogeneous curve (w*P, w).
  std::vector<Eigen::Vector4d> homogeneous(max_derivative + 1, Eigen::Vector4d::Zero());
  for (int k = 0; k <= max_derivative; ++k) {
    for (int j = 0; j < curve.order; ++j) {
      const int i = span - curve.order + 1 + j;
      const double w = curve.weight(i);
      homogeneous[k].head<3>() += basis[k][j] * w * curve.points[i];
      homogeneous[k][3] += basis[k][j] * w;
    }
  }
  return rational_curve_derivatives(homogeneous);
}

namespace {

// curve_point for an order known at compile time (0: the curve's), which unrolls the basis: the same
// sums in the same order, so bit for bit the same point.
template <int Order>
Eigen::Vector3d point_of_order(const NurbsCurve& curve, double t) {
  const int order = Order > 0 ? Order : curve.order;
  const int span = find_knot_span(curve.knots, order, curve.count(), t);
  double basis[kMaxStackOrder], left[kMaxStackOrder], right[kMaxStackOrder];
  basis_function_values(curve.knots.data(), order, span, t, basis, left, right);
  Eigen::Vector4d homogeneous = Eigen::Vector4d::Zero();
  for (int j = 0; j < order; ++j) {
    const int i = span - order + 1 + j;
    const double w = curve.weight(i);
    homogeneous.head<3>() += basis[j] * w * curve.points[i];
    homogeneous[3] += basis[j] * w;
  }
  return homogeneous.head<3>() / homogeneous[3];
}

}  // namespace

Eigen::Vector3d curve_point(const NurbsCurve& curve, double t) {
  if (curve.order > kMaxStackOrder) return curve_derivatives(curve, t, 0)[0];
  // The hot path of trim sampling and inversion: no allocation; lines, conics and cubics unrolled.
  switch (curve.order) {
    case 2: return point_of_order<2>(curve, t);
    case 3: return point_of_order<3>(curve, t);
    case 4: return point_of_order<4>(curve, t);
    default: return point_of_order<0>(curve, t);
  }
}

NurbsCurve reversed(const NurbsCurve& curve) {
  NurbsCurve out = curve;
  const double a = curve.domain_start(), b = curve.domain_end();
  const size_t m = curve.knots.size();
  for (size_t i = 0; i < m; ++i) out.knots[i] = a + b - curve.knots[m - 1 - i];
  std::reverse(out.points.begin(), out.points.end());
  std::reverse(out.weights.begin(), out.weights.end());
  return out;
}

}  // namespace cadnurbs
