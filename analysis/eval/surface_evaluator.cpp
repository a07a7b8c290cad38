#include "analysis/eval/surface_evaluator.hpp"

#include <algorithm>

#include "core/geometry_error.hpp"
#include "core/knot_vector.hpp"

namespace cadnurbs {

namespace {

constexpr int kMax = SurfaceEvaluator::max_order;

}  // namespace

SurfaceEvaluator::SurfaceEvaluator(const NurbsSurface& s)
    : surface_(&s),
      u_order_(s.u_order),
      v_order_(s.v_order),
      u_count_(s.u_count),
      v_count_(s.v_count),
      u_knots_(s.u_knots),
      v_knots_(s.v_knots),
      rational_(s.is_rational()),
      point_(point_function(s.u_order, s.v_order)) {
  if (s.u_order > kMax || s.v_order > kMax)
    throw GeometryError("surface evaluator", "order " + std::to_string(std::max(s.u_order, s.v_order)) +
                                                 " is above the supported " + std::to_string(kMax));
  homogeneous_.resize(s.points.size());
  for (size_t i = 0; i < s.points.size(); ++i) {
    const double w = s.weights.empty() ? 1.0 : s.weights[i];
    homogeneous_[i] << w * s.points[i], w;
  }
}

Eigen::Vector3d SurfaceEvaluator::point(double u, double v) const { return (this->*point_)(u, v); }

// jet(u, v, 0).s without the derivative rows, for orders known at compile time (0: the surface's):
// the same sums in the same order, so bit for bit the same point, at a fraction of the cost (the
// certification's lattices and the trim sampling evaluate points only).
template <int OU, int OV>
Eigen::Vector3d SurfaceEvaluator::point_of_orders(double u, double v) const {
  const int ou = OU > 0 ? OU : u_order_, ov = OV > 0 ? OV : v_order_;
  u = std::clamp(u, u_start(), u_end());
  v = std::clamp(v, v_start(), v_end());
  const int us = find_knot_span(u_knots_, ou, u_count_, u);
  const int vs = find_knot_span(v_knots_, ov, v_count_, v);
  double nu[kMax], nv[kMax], left[kMax], right[kMax];
  basis_function_values(u_knots_.data(), ou, us, u, nu, left, right);
  basis_function_values(v_knots_.data(), ov, vs, v, nv, left, right);
  Eigen::Vector4d h = Eigen::Vector4d::Zero();
  const int i0 = us - ou + 1, j0 = vs - ov + 1;
  for (int b = 0; b < ov; ++b) {
    Eigen::Vector4d row = Eigen::Vector4d::Zero();
    const Eigen::Vector4d* line = &homogeneous_[static_cast<size_t>(i0) + static_cast<size_t>(j0 + b) * u_count_];
    for (int a = 0; a < ou; ++a) row += nu[a] * line[a];
    h += nv[b] * row;
  }
  if (!rational_) return h.head<3>();
  return h.head<3>() / h[3];
}

SurfaceEvaluator::PointFunction SurfaceEvaluator::point_function(int u_order, int v_order) {
  // Planes (2 x 2), cylinders and cones (3 x 2), spheres and tori (3 x 3) as exact NURBS, and cubic
  // B-splines (4 x 4) are most faces.
  static constexpr PointFunction table[3][3] = {
      {&SurfaceEvaluator::point_of_orders<2, 2>, &SurfaceEvaluator::point_of_orders<2, 3>,
       &SurfaceEvaluator::point_of_orders<2, 4>},
      {&SurfaceEvaluator::point_of_orders<3, 2>, &SurfaceEvaluator::point_of_orders<3, 3>,
       &SurfaceEvaluator::point_of_orders<3, 4>},
      {&SurfaceEvaluator::point_of_orders<4, 2>, &SurfaceEvaluator::point_of_orders<4, 3>,
       &SurfaceEvaluator::point_of_orders<4, 4>}};
  if (u_order >= 2 && u_order <= 4 && v_order >= 2 && v_order <= 4) return table[u_order - 2][v_order - 2];
  return &SurfaceEvaluator::point_of_orders<0, 0>;
}

SurfaceJet SurfaceEvaluator::jet(double u, double v, int order) const {
  u = std::clamp(u, u_start(), u_end());
  v = std::clamp(v, v_start(), v_end());
  const int us = find_knot_span(u_knots_, u_order_, u_count_, u);
  const int vs = find_knot_span(v_knots_, v_order_, v_count_, v);
  double nu[3][kMax], nv[3][kMax];
  basis_function_derivatives(u_knots_, u_order_, us, u, order, &nu[0][0], kMax);
  basis_function_derivatives(v_knots_, v_order_, vs, v, order, &nv[0][0], kMax);
  // Homogeneous derivatives h[k][l] = d^{k+l}(wP, w)/du^k dv^l, k + l <= order.
  Eigen::Vector4d h[3][3];
  for (auto& row : h)
    for (auto& x : row) x.setZero();
  const int i0 = us - u_order_ + 1, j0 = vs - v_order_ + 1;
  for (int b = 0; b < v_order_; ++b) {
    Eigen::Vector4d row[3] = {Eigen::Vector4d::Zero(), Eigen::Vector4d::Zero(), Eigen::Vector4d::Zero()};
    const Eigen::Vector4d* line = &homogeneous_[static_cast<size_t>(i0) + static_cast<size_t>(j0 + b) * u_count_];
    for (int a = 0; a < u_order_; ++a)
      for (int k = 0; k <= order; ++k) row[k] += nu[k][a] * line[a];
    for (int k = 0; k <= order; ++k)
      for (int l = 0; l <= order - k; ++l) h[k][l] += nv[l][b] * row[k];
  }
  SurfaceJet out;
  out.s = out.su = out.sv = out.suu = out.suv = out.svv = Eigen::Vector3d::Zero();
  if (!rational_) {
    out.s = h[0][0].head<3>();
    if (order >= 1) out.su = h[1][0].head<3>(), out.sv = h[0][1].head<3>();
    if (order >= 2) out.suu = h[2][0].head<3>(), out.suv = h[1][1].head<3>(), out.svv = h[0][2].head<3>();
    return out;
  }
  // Quotient rule: w S = A, so S = A / w, w S_u = A_u - w_u S, ... (Piegl & Tiller A4.4).
  const double w = h[0][0][3];
  out.s = h[0][0].head<3>() / w;
  if (order >= 1) {
    out.su = (h[1][0].head<3>() - h[1][0][3] * out.s) / w;
    out.sv = (h[0][1].head<3>() - h[0][1][3] * out.s) / w;
  }
  if (order >= 2) {
    out.suu = (h[2][0].head<3>() - 2 * h[1][0][3] * out.su - h[2][0][3] * out.s) / w;
    out.svv = (h[0][2].head<3>() - 2 * h[0][1][3] * out.sv - h[0][2][3] * out.s) / w;
    out.suv = (h[1][1].head<3>() - h[1][0][3] * out.sv - h[0][1][3] * out.su - h[1][1][3] * out.s) / w;
  }
  return out;
}

}  // namespace cadnurbs
