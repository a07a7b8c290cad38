#include "core/nurbs_surface.hpp"

#include <algorithm>
#include <cmath>

#include "core/geometry_error.hpp"
#include "core/knot_vector.hpp"
#include "core/rational_derivatives.hpp"

namespace cadnurbs {

void validate(const NurbsSurface& s, const std::string& entity) {
  if (const std::string fault = knot_vector_fault(s.u_knots, s.u_order, s.u_count); !fault.empty())
    throw GeometryError(entity, "u: " + fault);
  if (const std::string fault = knot_vector_fault(s.v_knots, s.v_order, s.v_count); !fault.empty())
    throw GeometryError(entity, "v: " + fault);
  const size_t n = static_cast<size_t>(s.u_count) * s.v_count;
  if (s.points.size() != n)
    throw GeometryError(entity, std::to_string(s.points.size()) + " control points given, but " +
                                    std::to_string(s.u_count) + " x " + std::to_string(s.v_count) + " = " +
                                    std::to_string(n) + " needed");
  if (!s.weights.empty() && s.weights.size() != n)
    throw GeometryError(entity, std::to_string(s.weights.size()) + " weights for " + std::to_string(n) +
                                    " control points");
  for (size_t i = 0; i < s.weights.size(); ++i)
    if (!(s.weights[i] > 0.0) || !std::isfinite(s.weights[i]))
      throw GeometryError(entity, "weight " + std::to_string(i) + " is " + std::to_string(s.weights[i]) +
                                      "; weights must be positive");
  for (size_t i = 0; i < n; ++i)
    if (!s.points[i].allFinite()) throw GeometryError(entity, "control point " + std::to_string(i) + " is not finite");
}

std::vector<std::vector<Eigen::Vector3d>> surface_derivatives(const NurbsSurface& s, double u, double v,
                                                              int max_derivative) {
  const int d = max_derivative;
  const int uspan = find_knot_span(s.u_knots, s.u_order, s.u_count, u);
  const int vspan = find_knot_span(s.v_knots, s.v_order, s.v_count, v);
  const auto nu = basis_function_derivatives(s.u_knots, s.u_order, uspan, u, d);
  const auto nv = basis_function_derivatives(s.v_knots, s.v_order, vspan, v, d);
  std::vector<std::vector<Eigen::Vector4d>> h(d + 1, std::vector<Eigen::Vector4d>(d + 1, Eigen::Vector4d::Zero()));
  for (int k = 0; k <= d; ++k) {
    for (int l = 0; l <= d - k; ++l) {
      Eigen::Vector4d sum = Eigen::Vector4d::Zero();
      for (int b = 0; b < s.v_order; ++b) {
        const int j = vspan - s.v_order + 1 + b;
        Eigen::Vector4d row = Eigen::Vector4d::Zero();
        for (int a = 0; a < s.u_order; ++a) {
          const int i = uspan - s.u_order + 1 + a;
          const double w = s.weight(i, j);
          Eigen::Vector4d pw;
          pw << w * s.point(i, j), w;
          row += nu[k][a] * pw;
        }
        sum += nv[l][b] * row;
      }
      h[k][l] = sum;
    }
  }
  return rational_surface_derivatives(h);
}

// The hot path of trim fitting and inversion: no allocation (surface_derivatives allocates its tables).
// The same sums in the same order as surface_derivatives at order 0, so bit for bit the same point.
Eigen::Vector3d surface_point(const NurbsSurface& s, double u, double v) {
  if (s.u_order > kMaxStackOrder || s.v_order > kMaxStackOrder) return surface_derivatives(s, u, v, 0)[0][0];
  const int uspan = find_knot_span(s.u_knots, s.u_order, s.u_count, u);
  const int vspan = find_knot_span(s.v_knots, s.v_order, s.v_count, v);
  double nu[kMaxStackOrder], nv[kMaxStackOrder], left[kMaxStackOrder], right[kMaxStackOrder];
  basis_function_values(s.u_knots.data(), s.u_order, uspan, u, nu, left, right);
  basis_function_values(s.v_knots.data(), s.v_order, vspan, v, nv, left, right);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double weight_sum = 0;
  const bool rational = s.is_rational();
  for (int b = 0; b < s.v_order; ++b) {
    const int j = vspan - s.v_order + 1 + b;
    Eigen::Vector3d row = Eigen::Vector3d::Zero();
    double row_weight = 0;
    for (int a = 0; a < s.u_order; ++a) {
      const int i = uspan - s.u_order + 1 + a;
      if (rational) {
        const double w = s.weights[s.index(i, j)];
        row += nu[a] * (w * s.point(i, j));
        row_weight += nu[a] * w;
      } else {  // w = 1: the same products
        row += nu[a] * s.point(i, j);
        row_weight += nu[a];
      }
    }
    sum += nv[b] * row;
    weight_sum += nv[b] * row_weight;
  }
  return sum / weight_sum;
}

Eigen::Vector3d surface_normal(const NurbsSurface& s, double u, double v) {
  const double du = (s.u_end() - s.u_start()), dv = (s.v_end() - s.v_start());
  // At a pole Su or Sv vanishes; the limit normal is found a little inside the domain.
  for (double step : {0.0, 1e-7, 1e-5, 1e-3}) {
    const double uu = u + (u < s.u_start() + 0.5 * du ? step : -step) * du;
    const double vv = v + (v < s.v_start() + 0.5 * dv ? step : -step) * dv;
    const auto d = surface_derivatives(s, uu, vv, 1);
    const Eigen::Vector3d n = d[1][0].cross(d[0][1]);
    const double scale = d[1][0].norm() * d[0][1].norm();
    if (scale > 0 && n.norm() > 1e-10 * scale) return n.normalized();
  }
  return Eigen::Vector3d::Zero();
}

double surface_derivative_bound(const NurbsSurface& s) {
  double bound = 0.0;
  for (int j = 0; j < s.v_count; ++j)
    for (int i = 0; i + 1 < s.u_count; ++i) {
      const double span = s.u_knots[i + s.u_order] - s.u_knots[i + 1];
      if (span > 0.0) bound = std::max(bound, (s.u_order - 1) * (s.point(i + 1, j) - s.point(i, j)).norm() / span);
    }
  for (int i = 0; i < s.u_count; ++i)
    for (int j = 0; j + 1 < s.v_count; ++j) {
      const double span = s.v_knots[j + s.v_order] - s.v_knots[j + 1];
      if (span > 0.0) bound = std::max(bound, (s.v_order - 1) * (s.point(i, j + 1) - s.point(i, j)).norm() / span);
    }
  if (s.is_rational()) {
    const auto [lo, hi] = std::minmax_element(s.weights.begin(), s.weights.end());
    bound *= (*hi / *lo) * (*hi / *lo);
  }
  return bound;
}

double trim_parameter_tolerance(const NurbsSurface& surface, double tau) {
  const double domain = std::max(surface.u_end() - surface.u_start(), surface.v_end() - surface.v_start());
  const double bound = surface_derivative_bound(surface);
  double tolerance = 1e-3 * domain;
  if (bound > 0.0) tolerance = std::min(tolerance, 0.1 * tau / bound);
  return tolerance;
}

}  // namespace cadnurbs
