#pragma once
// Fast evaluation of a NURBS surface and its derivatives up to order 2, without heap allocation per
// call. core::surface_derivatives is the reference (and allocates); tessellation and deviation
// measurement evaluate millions of points, so they use this. Same algorithms (Piegl & Tiller A2.1,
// A2.3 for the basis, quotient rule for the rational part).
#include <Eigen/Core>
#include <vector>

#include "core/knot_vector.hpp"
#include "core/nurbs_surface.hpp"

namespace cadnurbs {

// Point and derivatives at one (u, v): s, su, sv always; suu, suv, svv when order 2 was asked for.
struct SurfaceJet {
  Eigen::Vector3d s, su, sv, suu, suv, svv;
};

class SurfaceEvaluator {
 public:
  // Highest order (degree + 1) supported; OCCT and IGES stop at degree 25.
  static constexpr int max_order = kMaxStackOrder;

  // Takes a validated surface; refuses (GeometryError "surface evaluator") orders above max_order.
  explicit SurfaceEvaluator(const NurbsSurface& surface);

  // Point at (u, v), clamped to the domain.
  Eigen::Vector3d point(double u, double v) const;

  // Derivatives up to `order` (0, 1 or 2) at (u, v), clamped to the domain; unset fields stay zero.
  SurfaceJet jet(double u, double v, int order) const;

  double u_start() const { return u_knots_[u_order_ - 1]; }
  double u_end() const { return u_knots_[u_count_]; }
  double v_start() const { return v_knots_[v_order_ - 1]; }
  double v_end() const { return v_knots_[v_count_]; }
  const NurbsSurface& surface() const { return *surface_; }

 private:
  const NurbsSurface* surface_;
  int u_order_, v_order_, u_count_, v_count_;
  std::vector<double> u_knots_, v_knots_;
  std::vector<Eigen::Vector4d> homogeneous_;  // (w P, w), u fastest
  bool rational_;
  using PointFunction = Eigen::Vector3d (SurfaceEvaluator::*)(double, double) const;
  PointFunction point_;  // point_of_orders for this surface's orders

  template <int OU, int OV>
  Eigen::Vector3d point_of_orders(double u, double v) const;
  static PointFunction point_function(int u_order, int v_order);
};

}  // namespace cadnurbs
