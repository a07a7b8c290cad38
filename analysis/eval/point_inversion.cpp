#include "analysis/eval/point_inversion.hpp"

#include <algorithm>
#include <cmath>

#include "core/trim_segment_parameters.hpp"

namespace cadnurbs {

SurfaceProjection project_to_surface(const SurfaceEvaluator& surface, const Eigen::Vector3d& p,
                                     const Eigen::Vector2d& start, int max_iterations) {
  const double u0 = surface.u_start(), u1 = surface.u_end(), v0 = surface.v_start(), v1 = surface.v_end();
  Eigen::Vector2d uv(std::clamp(start.x(), u0, u1), std::clamp(start.y(), v0, v1));
  SurfaceJet j = surface.jet(uv.x(), uv.y(), 2);
  double dist = (j.s - p).norm();
  for (int it = 0; it < max_iterations && dist > 0; ++it) {
    const Eigen::Vector3d r = j.s - p;
    const Eigen::Vector2d g(j.su.dot(r), j.sv.dot(r));
    Eigen::Matrix2d jtj;
    jtj << j.su.dot(j.su), j.su.dot(j.sv), j.su.dot(j.sv), j.sv.dot(j.sv);
    Eigen::Matrix2d h = jtj;
    h(0, 0) += r.dot(j.suu), h(0, 1) += r.dot(j.suv), h(1, 0) += r.dot(j.suv), h(1, 1) += r.dot(j.svv);
    // Full Newton where it is a descent method; Gauss-Newton (always positive semi-definite) otherwise.
    Eigen::Matrix2d m = (h.determinant() > 0 && h(0, 0) > 0) ? h : jtj;
    if (!(m.determinant() > 1e-300)) m += Eigen::Matrix2d::Identity() * (1e-12 * (jtj.trace() + 1e-300));
    Eigen::Vector2d step = -m.inverse() * g;
    if (!step.allFinite()) break;
    // Converged when the model's decrease of |r|^2 / 2 is below rounding (see project_to_trim_curve).
    if (-0.5 * g.dot(step) <= 1e-15 * (1 + dist) * dist) break;
    bool improved = false;
    for (int half = 0; half < 12; ++half, step *= 0.5) {
      const Eigen::Vector2d next(std::clamp(uv.x() + step.x(), u0, u1), std::clamp(uv.y() + step.y(), v0, v1));
      const SurfaceJet jn = surface.jet(next.x(), next.y(), 2);
      const double dn = (jn.s - p).norm();
      if (dn < dist) {
        const double moved = (next - uv).norm();
        uv = next, j = jn, improved = true;
        const bool converged = dist - dn <= 1e-15 * (1 + dist) || moved <= 1e-15 * (1 + uv.norm());
        dist = dn;
        if (converged) return {uv, j.s, dist};
        break;
      }
    }
    if (!improved) break;
  }
  return {uv, j.s, dist};
}

CurveProjection project_to_trim_curve(const SurfaceEvaluator& surface, const TrimSegment& segment,
                                      const Eigen::Vector3d& p, double t_start, double t_lo, double t_hi,
                                      int max_iterations) {
  double t = std::clamp(t_start, t_lo, t_hi);
  auto eval = [&](double tt, Eigen::Vector2d& uv, SurfaceJet& j) {
    uv = segment_uv(segment, tt);
    j = surface.jet(uv.x(), uv.y(), 1);
  };
  Eigen::Vector2d uv;
  SurfaceJet j;
  eval(t, uv, j);
  double dist = (j.s - p).norm();
  for (int it = 0; it < max_iterations && dist > 0; ++it) {
    const Eigen::Vector2d dc = segment_tangent(segment, t);
    const Eigen::Vector3d ct = j.su * dc.x() + j.sv * dc.y();
    const double denom = ct.squaredNorm();
    if (!(denom > 0)) break;
    const double slope = (j.s - p).dot(ct);
    double step = -slope / denom;
    // Converged when the step cannot lower the distance by more than rounding: near the minimum the
    // distance is flat to within sqrt(epsilon) of t, and the halvings below would only fail.
    if (slope * slope / (2 * denom) <= 1e-15 * (1 + dist) * dist) break;
    bool improved = false;
    for (int half = 0; half < 12; ++half, step *= 0.5) {
      const double tn = std::clamp(t + step, t_lo, t_hi);
      Eigen::Vector2d uvn;
      SurfaceJet jn;
      eval(tn, uvn, jn);
      const double dn = (jn.s - p).norm();
      if (dn < dist) {
        const bool converged = dist - dn <= 1e-15 * (1 + dist) || std::abs(tn - t) <= 1e-15 * (1 + std::abs(t));
        t = tn, uv = uvn, j = jn, dist = dn, improved = true;
        if (converged) return {t, uv, j.s, dist};
        break;
      }
    }
    if (!improved) break;
  }
  return {t, uv, j.s, dist};
}

}  // namespace cadnurbs
