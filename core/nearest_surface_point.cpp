#include "core/nearest_surface_point.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/knot_vector.hpp"

namespace cadnurbs {

namespace {

struct Jet {
  Eigen::Vector3d s, su, sv, suu, suv, svv;
};

Jet surface_jet(const NurbsSurface& surface, const Eigen::Vector2d& uv) {
  const auto d = surface_derivatives(surface, uv.x(), uv.y(), 2);
  return {d[0][0], d[1][0], d[0][1], d[2][0], d[1][1], d[0][2]};
}

// The Newton step for gradient g and matrix m; a coordinate held at a side of the domain that the step
// would leave is fixed there and the other solved alone (the minimum along that side).
Eigen::Vector2d constrained_step(const Eigen::Matrix2d& m, const Eigen::Vector2d& g, const Eigen::Vector2d& uv,
                                 const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) {
  Eigen::Vector2d step = -m.inverse() * g;
  for (int k = 0; k < 2; ++k) {
    const bool leaves = (uv[k] <= lo[k] && step[k] < 0) || (uv[k] >= hi[k] && step[k] > 0);
    if (!leaves) continue;
    const int o = 1 - k;
    step[k] = 0.0;
    step[o] = m(o, o) > 0 ? -g[o] / m(o, o) : 0.0;
    if ((uv[o] <= lo[o] && step[o] < 0) || (uv[o] >= hi[o] && step[o] > 0)) step[o] = 0.0;  // a corner
    break;
  }
  return step;
}

// Grid parameters in one direction: 3 per non-empty knot span (more when there are few spans, so
// that there are at least 8), and the domain's end.
std::vector<double> grid_parameters(const std::vector<double>& knots, int order, int count) {
  const std::vector<double> breaks = domain_breaks(knots, order, count);
  const int spans = static_cast<int>(breaks.size()) - 1;
  const int per_span = std::max(3, (8 + spans - 1) / std::max(spans, 1));
  std::vector<double> t;
  for (int s = 0; s < spans; ++s)
    for (int i = 0; i < per_span; ++i) t.push_back(breaks[s] + (breaks[s + 1] - breaks[s]) * i / per_span);
  t.push_back(breaks.back());
  return t;
}

// The non-zero basis values at each parameter: spans[i] and values[i * order .. + order).
struct BasisRow {
  std::vector<int> spans;
  std::vector<double> values;
};

BasisRow basis_rows(const std::vector<double>& knots, int order, int count, const std::vector<double>& t) {
  BasisRow rows{std::vector<int>(t.size()), std::vector<double>(t.size() * order)};
  for (size_t i = 0; i < t.size(); ++i) {
    rows.spans[i] = find_knot_span(knots, order, count, t[i]);
    basis_function_derivatives(knots, order, rows.spans[i], t[i], 0, &rows.values[i * order], order);
  }
  return rows;
}

}  // namespace

Eigen::Vector2d nearest_surface_parameter(const NurbsSurface& surface, const Eigen::Vector3d& p,
                                          const Eigen::Vector2d& start) {
  const Eigen::Vector2d lo(surface.u_start(), surface.v_start()), hi(surface.u_end(), surface.v_end());
  auto clamp = [&](const Eigen::Vector2d& q) { return Eigen::Vector2d(q.cwiseMax(lo).cwiseMin(hi)); };
  Eigen::Vector2d uv = start.allFinite() ? clamp(start) : lo;
  if (!p.allFinite()) return uv;
  Jet j = surface_jet(surface, uv);
  double dist = (j.s - p).norm();
  // A step that moves the surface point by less than this is rounding: taken without comparing
  // distances (near the minimum they are flat to rounding and halving would only waste evaluations).
  const double tiny = 1e-13 * (1.0 + p.norm());
  for (int iteration = 0; iteration < 30 && dist > 0; ++iteration) {
    const Eigen::Vector3d r = j.s - p;
    const Eigen::Vector2d g(j.su.dot(r), j.sv.dot(r));
    Eigen::Matrix2d gauss_newton;
    gauss_newton << j.su.dot(j.su), j.su.dot(j.sv), j.su.dot(j.sv), j.sv.dot(j.sv);
    Eigen::Matrix2d hessian = gauss_newton;
    hessian(0, 0) += r.dot(j.suu), hessian(1, 1) += r.dot(j.svv);
    hessian(0, 1) += r.dot(j.suv), hessian(1, 0) += r.dot(j.suv);
    // Full Newton only where it descends; Gauss-Newton (positive semi-definite) otherwise, nudged off
    // singular at poles where a derivative vanishes.
    Eigen::Matrix2d m = (hessian(0, 0) > 0 && hessian.determinant() > 0) ? hessian : gauss_newton;
    if (!(m.trace() > 0)) break;  // both derivatives vanish: nothing to steer by
    if (!(m.determinant() > 1e-14 * m.trace() * m.trace())) m += 1e-7 * m.trace() * Eigen::Matrix2d::Identity();
    Eigen::Vector2d step = constrained_step(m, g, uv, lo, hi);
    if (!step.allFinite() || step.isZero()) break;
    // Also a step too short to change the distance measurably (its square below rounding of it):
    // Newton's last, quadratically convergent steps off the surface.
    const double moves = (j.su * step.x() + j.sv * step.y()).norm();
    if (moves <= tiny || moves <= 1e-7 * dist) return clamp(uv + step);
    bool improved = false;
    for (int half = 0; half < 30 && !improved; ++half, step *= 0.5) {
      const Eigen::Vector2d next = clamp(uv + step);
      const Jet jn = surface_jet(surface, next);
      const double dn = (jn.s - p).norm();
      if (dn < dist) {
        const bool converged = (next - uv).norm() <= 1e-15 * (1.0 + uv.norm());
        uv = next, j = jn, dist = dn, improved = true;
        if (converged) return uv;
      }
    }
    if (!improved) break;
  }
  return uv;
}

Eigen::Vector2d nearest_surface_parameter(const NurbsSurface& surface, const Eigen::Vector3d& p) {
  const std::vector<double> us = grid_parameters(surface.u_knots, surface.u_order, surface.u_count);
  const std::vector<double> vs = grid_parameters(surface.v_knots, surface.v_order, surface.v_count);
  if (!p.allFinite()) return {us.front(), vs.front()};
  // The grid from the basis values of each row and column: u_order x v_order products a point.
  const BasisRow bu = basis_rows(surface.u_knots, surface.u_order, surface.u_count, us);
  const BasisRow bv = basis_rows(surface.v_knots, surface.v_order, surface.v_count, vs);
  const int ku = surface.u_order, kv = surface.v_order;
  const size_t nu = us.size(), nv = vs.size();
  std::vector<double> d2(nu * nv);
  for (size_t b = 0; b < nv; ++b)
    for (size_t a = 0; a < nu; ++a) {
      Eigen::Vector4d sum = Eigen::Vector4d::Zero();
      for (int l = 0; l < kv; ++l) {
        const int jj = bv.spans[b] - kv + 1 + l;
        for (int k = 0; k < ku; ++k) {
          const int ii = bu.spans[a] - ku + 1 + k;
          const double w = surface.weight(ii, jj);
          const double n = bu.values[a * ku + k] * bv.values[b * kv + l];
          sum.head<3>() += (n * w) * surface.point(ii, jj);
          sum.w() += n * w;
        }
      }
      d2[a + b * nu] = (sum.head<3>() / sum.w() - p).squaredNorm();
    }
  // Newton from the grid's local minima, nearest first, at most 4: on a closed surface both sides of
  // the seam are minima, and the nearer one may be the side Newton cannot reach from the other.
  std::vector<std::pair<double, size_t>> minima;
  for (size_t b = 0; b < nv; ++b)
    for (size_t a = 0; a < nu; ++a) {
      bool minimum = true;
      for (size_t bb = b > 0 ? b - 1 : 0; bb <= std::min(b + 1, nv - 1) && minimum; ++bb)
        for (size_t aa = a > 0 ? a - 1 : 0; aa <= std::min(a + 1, nu - 1); ++aa)
          if (d2[aa + bb * nu] < d2[a + b * nu]) minimum = false;
      if (minimum) minima.emplace_back(d2[a + b * nu], a + b * nu);
    }
  std::sort(minima.begin(), minima.end());
  minima.resize(std::min<size_t>(minima.size(), 4));
  Eigen::Vector2d best(us.front(), vs.front());
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto& [unused, index] : minima) {
    const Eigen::Vector2d uv = nearest_surface_parameter(surface, p, {us[index % nu], vs[index / nu]});
    const double d = (surface_point(surface, uv.x(), uv.y()) - p).squaredNorm();
    if (d < nearest) nearest = d, best = uv;
  }
  return best;
}

}  // namespace cadnurbs
