#include "formats/vrml/nurbs_tolerances.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cadnurbs {

namespace {

struct NetMeasures {
  double w_min = 1.0, w_max = 1.0;
  double extent = 0.0;     // D
  double magnitude = 0.0;  // M
};

NetMeasures measure(const std::vector<Eigen::Vector3d>& points, const std::vector<double>& weights) {
  NetMeasures m;
  if (!weights.empty()) {
    m.w_min = *std::min_element(weights.begin(), weights.end());
    m.w_max = *std::max_element(weights.begin(), weights.end());
  }
  Eigen::AlignedBox3d box;
  for (const auto& p : points) {
    box.extend(p);
    m.magnitude = std::max(m.magnitude, p.cwiseAbs().maxCoeff());
  }
  if (!points.empty()) m.extent = box.sizes().maxCoeff();
  return m;
}

// Smallest non-empty span of a knot vector (0 if all knots are equal).
double shortest_span(const std::vector<double>& knots) {
  double shortest = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i + 1 < knots.size(); ++i)
    if (knots[i + 1] > knots[i]) shortest = std::min(shortest, knots[i + 1] - knots[i]);
  return std::isfinite(shortest) ? shortest : 0.0;
}

double knot_tolerance(double tau, double span, int order, const NetMeasures& m) {
  const double pull = order * m.extent * (m.w_max / m.w_min);
  double tolerance = 1e-3 * span;
  if (pull > 0.0) tolerance = std::min(tolerance, 0.25 * tau * span / pull);
  return tolerance;
}

NurbsTolerances tolerances(const NetMeasures& m, double tau, bool homogeneous, double knot_tol) {
  NurbsTolerances t;
  t.control_point = homogeneous ? 0.5 * tau * m.w_min : 0.5 * tau;
  const double reach = homogeneous ? m.magnitude : m.extent;
  t.weight = 0.01 * m.w_min;
  if (reach > 0.0) t.weight = std::min(t.weight, 0.25 * tau * m.w_min / reach);
  t.knot = knot_tol;
  return t;
}

}  // namespace

NurbsTolerances surface_tolerances(const NurbsSurface& surface, double tau, bool homogeneous) {
  const NetMeasures m = measure(surface.points, surface.weights);
  const double knot_tol = std::min(knot_tolerance(tau, shortest_span(surface.u_knots), surface.u_order, m),
                                   knot_tolerance(tau, shortest_span(surface.v_knots), surface.v_order, m));
  return tolerances(m, tau, homogeneous, knot_tol);
}

NurbsTolerances curve_tolerances(const NurbsCurve& curve, double tau, bool homogeneous) {
  const NetMeasures m = measure(curve.points, curve.weights);
  return tolerances(m, tau, homogeneous, knot_tolerance(tau, shortest_span(curve.knots), curve.order, m));
}

}  // namespace cadnurbs
