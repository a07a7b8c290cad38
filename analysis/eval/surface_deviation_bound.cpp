#include "analysis/eval/surface_deviation_bound.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/eval/rational_derivative_bound.hpp"
#include "core/bezier_extraction.hpp"
#include "core/knot_vector.hpp"

namespace cadnurbs {

namespace {

constexpr int kNumeratorBoundDegree = 3;

SecondDerivativeBound patch_bound(const NurbsSurface& patch) {
  const int p = patch.u_order - 1, q = patch.v_order - 1;
  const double du = patch.u_end() - patch.u_start(), dv = patch.v_end() - patch.v_start();
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& pt : patch.points) c += pt;
  c /= static_cast<double>(patch.points.size());
  double radius = 0, wmin = 1e300;
  std::vector<Eigen::Vector4d> net(patch.points.size());
  for (int j = 0; j <= q; ++j)
    for (int i = 0; i <= p; ++i) {
      const double w = patch.weight(i, j);
      const Eigen::Vector3d d = patch.point(i, j) - c;
      radius = std::max(radius, d.norm());
      wmin = std::min(wmin, w);
      net[patch.index(i, j)] << w * d, w;
    }
  auto at = [&](int i, int j) -> const Eigen::Vector4d& { return net[patch.index(i, j)]; };
  // Largest xyz and w parts of a set of differences.
  struct Pair {
    double g = 0, w = 0;
    void take(const Eigen::Vector4d& d) { g = std::max(g, d.head<3>().norm()), w = std::max(w, std::abs(d[3])); }
  };
  Pair d1u, d1v, d2uu, d2uv, d2vv;
  for (int j = 0; j <= q; ++j)
    for (int i = 0; i <= p; ++i) {
      if (i + 1 <= p) d1u.take(at(i + 1, j) - at(i, j));
      if (j + 1 <= q) d1v.take(at(i, j + 1) - at(i, j));
      if (i + 2 <= p) d2uu.take(at(i + 2, j) - 2 * at(i + 1, j) + at(i, j));
      if (j + 2 <= q) d2vv.take(at(i, j + 2) - 2 * at(i, j + 1) + at(i, j));
      if (i + 1 <= p && j + 1 <= q) d2uv.take(at(i + 1, j + 1) - at(i + 1, j) - at(i, j + 1) + at(i, j));
    }
  // Bézier derivative bounds in the global parameters.
  const double f1u = p / du, f1v = q / dv;
  const double f2uu = p * (p - 1) / (du * du), f2vv = q * (q - 1) / (dv * dv), f2uv = p * q / (du * dv);
  const double gu = f1u * d1u.g, wu = f1u * d1u.w, gv = f1v * d1v.g, wv = f1v * d1v.w;
  const double guu = f2uu * d2uu.g, wuu = f2uu * d2uu.w, gvv = f2vv * d2vv.g, wvv = f2vv * d2vv.w;
  const double guv = f2uv * d2uv.g, wuv = f2uv * d2uv.w;
  SecondDerivativeBound m;
  if (!patch.is_rational()) {
    m.uu = guu, m.uv = guv, m.vv = gvv;
    return m;
  }
  // W S_u = G_u - W_u (S - c);  W S_uu = G_uu - 2 W_u S_u - W_uu (S - c); W S_uv = G_uv - W_u S_v - W_v S_u - W_uv (S - c).
  const double su = (gu + wu * radius) / wmin, sv = (gv + wv * radius) / wmin;
  m.uu = (guu + 2 * wu * su + wuu * radius) / wmin;
  m.vv = (gvv + 2 * wv * sv + wvv * radius) / wmin;
  m.uv = (guv + wu * sv + wv * su + wuv * radius) / wmin;
  // The numerators over W^3 (rational_derivative_bound.hpp) keep what cancels: a cylinder's S_uv is 0
  // there, where the quotient rule above gives a multiple of its radius. Both bound; the smaller holds.
  // Their products cost the fourth power of the degree: only on the low degrees conics and the
  // analytic surfaces come in (a degree 6 x 10 patch would cost more than tessellating it).
  if (p > kNumeratorBoundDegree || q > kNumeratorBoundDegree) return m;
  BernsteinPolynomial<Eigen::Vector3d> g(p, q, Eigen::Vector3d::Zero());
  BernsteinPolynomial<double> w(p, q, 0.0);
  for (int j = 0; j <= q; ++j)
    for (int i = 0; i <= p; ++i) g.at(i, j) = net[patch.index(i, j)].head<3>(), w.at(i, j) = net[patch.index(i, j)][3];
  const RationalDerivativeBound numerators = rational_derivative_bound(g, w, du, dv);
  m.uu = std::min(m.uu, numerators.uu), m.uv = std::min(m.uv, numerators.uv), m.vv = std::min(m.vv, numerators.vv);
  return m;
}

// Index range [first, last] of the cells of `b` meeting [x0, x1].
std::pair<int, int> cells(const std::vector<double>& b, double x0, double x1) {
  const int n = static_cast<int>(b.size()) - 1;
  int first = static_cast<int>(std::upper_bound(b.begin(), b.end(), x0) - b.begin()) - 1;
  int last = static_cast<int>(std::lower_bound(b.begin(), b.end(), x1) - b.begin()) - 1;
  first = std::clamp(first, 0, n - 1);
  last = std::clamp(last, first, n - 1);
  return {first, last};
}

}  // namespace

SecondDerivativeBound SurfaceDeviationBound::over(double u0, double u1, double v0, double v1) const {
  const auto [i0, i1] = cells(u_breaks, u0, u1);
  const auto [j0, j1] = cells(v_breaks, v0, v1);
  const int nu = static_cast<int>(u_breaks.size()) - 1;
  SecondDerivativeBound m;
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const auto& b = patches[i + j * nu];
      m.uu = std::max(m.uu, b.uu), m.uv = std::max(m.uv, b.uv), m.vv = std::max(m.vv, b.vv);
    }
  return m;
}

SurfaceDeviationBound surface_deviation_bound(const NurbsSurface& surface) {
  SurfaceDeviationBound out;
  out.u_breaks = domain_breaks(surface.u_knots, surface.u_order, surface.u_count);
  out.v_breaks = domain_breaks(surface.v_knots, surface.v_order, surface.v_count);
  out.c0_u = c0_knots(surface.u_knots, surface.u_order, surface.u_count);
  out.c0_v = c0_knots(surface.v_knots, surface.v_order, surface.v_count);
  for (const auto& patch : bezier_patches(surface)) out.patches.push_back(patch_bound(patch));
  return out;
}

double triangle_deviation_bound(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                                const SecondDerivativeBound& m) {
  if (m.uu == 0 && m.uv == 0 && m.vv == 0) return 0.0;
  // 2 |du dv| <= t du^2 + dv^2 / t with t = h_v / h_u (the triangle's extents) makes the bound FMM's
  // on grid triangles.
  const double hu = std::max({a.x(), b.x(), c.x()}) - std::min({a.x(), b.x(), c.x()});
  const double hv = std::max({a.y(), b.y(), c.y()}) - std::min({a.y(), b.y(), c.y()});
  double su = m.uu, sv = m.vv;
  // A triangle without extent in u or in v (a sliver along a seam) has no cross term at all.
  if (m.uv > 0 && hu > 0 && hv > 0) {
    const double t = hv / hu;
    su += t * m.uv;
    sv += m.uv / t;
  }
  const double ru = std::sqrt(su), rv = std::sqrt(sv);
  const Eigen::Vector2d p0(a.x() * ru, a.y() * rv), p1(b.x() * ru, b.y() * rv), p2(c.x() * ru, c.y() * rv);
  // max_x (sum lambda_i |p_i - x|^2) over the triangle = R^2 - dist(centre, triangle)^2; computed as
  // the smallest enclosing circle's squared radius when the circumcentre is outside (same value).
  const double l01 = (p1 - p0).squaredNorm(), l12 = (p2 - p1).squaredNorm(), l20 = (p0 - p2).squaredNorm();
  const double longest = std::max({l01, l12, l20});
  // Obtuse or right: the circumcentre is outside or on the longest edge; the maximum then lies on
  // that edge: (longest / 4).
  if (2 * longest >= l01 + l12 + l20) return 0.5 * longest / 4.0;
  const Eigen::Vector2d e1 = p1 - p0, e2 = p2 - p0;
  const double cross = e1.x() * e2.y() - e1.y() * e2.x();
  if (cross == 0) return 0.5 * longest / 4.0;
  const double r2 = l01 * l12 * l20 / (4.0 * cross * cross);  // (abc / 4K)^2, K = |cross| / 2
  return 0.5 * r2;
}

}  // namespace cadnurbs
