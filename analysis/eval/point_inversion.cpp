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
    // A last tiny step is taken as it is (see project_to_trim_curve).
    if ((j.su * step.x() + j.sv * step.y()).norm() <= 1e-9 * (1 + dist)) {
      uv = Eigen::Vector2d(std::clamp(uv.x() + step.x(), u0, u1), std::clamp(uv.y() + step.y(), v0, v1));
      const Eigen::Vector3d at = surface.point(uv.x(), uv.y());
      return {uv, at, (at - p).norm()};
    }
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
    double step = -(j.s - p).dot(ct) / denom;
    // A last step that moves the point by less than 1e-9 of the distance (plus one unit): taken as it
    // is. Near the minimum the distance is flat to rounding, so comparing distances there fails and
    // the halvings below would cost 12 evaluations for nothing.
    if (std::abs(step) * std::sqrt(denom) <= 1e-9 * (1 + dist)) {
      t = std::clamp(t + step, t_lo, t_hi);
      eval(t, uv, j);
      return {t, uv, j.s, (j.s - p).norm()};
    }
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
