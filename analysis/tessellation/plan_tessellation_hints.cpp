#include "analysis/tessellation/plan_tessellation_hints.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "analysis/eval/rational_derivative_bound.hpp"
#include "analysis/eval/surface_deviation_bound.hpp"
#include "analysis/eval/surface_evaluator.hpp"
#include "analysis/tessellation/sample_patch_curvature.hpp"
#include "core/bezier_extraction.hpp"
#include "core/knot_vector.hpp"

namespace cadnurbs {

namespace {

Eigen::Vector4d homogeneous(const Eigen::Vector3d& p, double w) { return {w * p.x(), w * p.y(), w * p.z(), w}; }

// Control-net bounds tighten as the pieces shrink (the net converges to the curve): every Bezier
// segment of a curved curve is split into this many equal pieces first (the shape does not change). 8
// brings the bounds within ~1.3x of the true second derivatives on circles.
constexpr int kRefinement = 8;

// Bezier segments (bezier_segments), each of degree >= 2 split into kRefinement equal pieces by de
// Casteljau's algorithm on the homogeneous points (linear in the segments, where inserting the knots
// one by one into the whole curve costs the square of their number).
std::vector<NurbsCurve> refined_pieces(const std::vector<NurbsCurve>& segments) {
  if (segments.empty() || segments.front().order <= 2) return segments;
  std::vector<NurbsCurve> out;
  out.reserve(segments.size() * kRefinement);
  const NurbsCurve& curve = segments.front();
  const int n = curve.order;
  for (const auto& segment : segments) {
    std::vector<Eigen::Vector4d> rest(n);  // the part not yet cut off, as (w P, w)
    for (int i = 0; i < n; ++i) rest[i] = homogeneous(segment.points[i], segment.weight(i));
    const double a = segment.domain_start(), b = segment.domain_end();
    std::vector<Eigen::Vector4d> left(n), work(n);
    for (int k = 0; k < kRefinement; ++k) {
      const double t0 = a + (b - a) * k / kRefinement, t1 = a + (b - a) * (k + 1) / kRefinement;
      if (k + 1 < kRefinement) {
        const double f = 1.0 / (kRefinement - k);  // where t1 falls in what is left
        work = rest;
        for (int level = 1; level < n; ++level) {
          left[level - 1] = work[0];
          for (int i = 0; i + level < n; ++i) work[i] = (1 - f) * work[i] + f * work[i + 1];
        }
        left[n - 1] = work[0];
        rest = work;  // updated in place, work[i] ends as b^(p-i)_i: the right part's point i
      } else {
        left = rest;
      }
      NurbsCurve piece;
      piece.dimension = curve.dimension;
      piece.order = n;
      piece.knots.assign(n, t0);
      piece.knots.insert(piece.knots.end(), n, t1);
      piece.points.resize(n);
      if (curve.is_rational()) piece.weights.resize(n);
      for (int i = 0; i < n; ++i) {
        piece.points[i] = left[i].head<3>() / left[i][3];
        if (curve.is_rational()) piece.weights[i] = left[i][3];
      }
      out.push_back(std::move(piece));
    }
  }
  return out;
}

// Bounds on one rational Bézier segment of a curve (rational_derivative_bound.hpp, as a piece with q = 0).
RationalDerivativeBound segment_bounds(const NurbsCurve& segment) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& q : segment.points) c += q;
  c /= static_cast<double>(segment.points.size());
  BernsteinPolynomial<Eigen::Vector3d> g(segment.order - 1, 0, Eigen::Vector3d::Zero());
  BernsteinPolynomial<double> w(segment.order - 1, 0, 0.0);
  for (int i = 0; i < segment.order; ++i) {
    w.at(i, 0) = segment.weight(i);
    g.at(i, 0) = segment.weight(i) * (segment.points[i] - c);
  }
  return rational_derivative_bound(g, w, segment.domain_end() - segment.domain_start(), 1.0);
}

// A C0 line (or point) of the parametrisation and the bound on the jump of the first derivative there.
struct Kink {
  double at = 0.0;
  double jump = 0.0;
};

// The kinks in u of `surface`: interior knots of multiplicity >= degree. Per v-span the jump of S_u
// across the line is (dG W - dW G) / W^2 along it, dG, dW the difference of the homogeneous
// derivatives from the control rows on both sides (Bézier form): bounded by its numerator's largest
// coefficient, exactly 0 where the parametrisation is C1 after all (the arcs of a rational circle).
std::vector<Kink> surface_kinks_u(const NurbsSurface& surface) {
  std::vector<Kink> out;
  const std::vector<double> c0_u = c0_knots(surface.u_knots, surface.u_order, surface.u_count);
  const int p = surface.u_order - 1;
  if (p < 1 || c0_u.empty()) return out;
  const std::vector<NurbsSurface> patches = bezier_patches(surface);
  const std::vector<double> u_breaks = domain_breaks(surface.u_knots, surface.u_order, surface.u_count);
  const int columns = static_cast<int>(u_breaks.size()) - 1;
  const int rows = static_cast<int>(domain_breaks(surface.v_knots, surface.v_order, surface.v_count).size()) - 1;
  for (const double k : c0_u) {
    const int i = static_cast<int>(std::lower_bound(u_breaks.begin(), u_breaks.end(), k) - u_breaks.begin());
    if (i <= 0 || i >= columns) continue;
    Kink kink{k, 0.0};
    for (int j = 0; j < rows; ++j) {
      const NurbsSurface& left = patches[(i - 1) + j * columns];
      const NurbsSurface& right = patches[i + j * columns];
      const double dl = left.u_end() - left.u_start(), dr = right.u_end() - right.u_start();
      // along the line (Bézier in v): G = w (P - c), W = w of the shared row, dG, dW the homogeneous
      // derivative difference across it; jump = (dG W - dW G) / W^2 (dG taken relative to c too)
      const int q = right.v_order - 1;
      Eigen::Vector3d c = Eigen::Vector3d::Zero();
      for (int l = 0; l <= q; ++l) c += right.point(0, l);
      c /= q + 1;
      BernsteinPolynomial<Eigen::Vector3d> g(q, 0, Eigen::Vector3d::Zero()), dg(q, 0, Eigen::Vector3d::Zero());
      BernsteinPolynomial<double> w(q, 0, 0.0), dw(q, 0, 0.0);
      double w_min = std::numeric_limits<double>::infinity();
      for (int l = 0; l <= q; ++l) {
        const Eigen::Vector4d d_right =
            p / dr * (homogeneous(right.point(1, l), right.weight(1, l)) - homogeneous(right.point(0, l), right.weight(0, l)));
        const Eigen::Vector4d d_left = p / dl * (homogeneous(left.point(p, l), left.weight(p, l)) -
                                                 homogeneous(left.point(p - 1, l), left.weight(p - 1, l)));
        const Eigen::Vector4d d = d_right - d_left;
        w.at(l, 0) = right.weight(0, l);
        g.at(l, 0) = right.weight(0, l) * (right.point(0, l) - c);
        dw.at(l, 0) = d[3];
        dg.at(l, 0) = d.head<3>() - d[3] * c;
        w_min = std::min(w_min, right.weight(0, l));
      }
      kink.jump = std::max(kink.jump, largest_coefficient(bernstein_sum(bernstein_product(dg, w), bernstein_product(g, dw), -1.0)) /
                                             (w_min * w_min));
    }
    if (kink.jump > 0.0) out.push_back(kink);
  }
  return out;
}

// The same surface with u and v exchanged (so one function serves both directions).
NurbsSurface transposed(const NurbsSurface& s) {
  NurbsSurface t;
  t.u_order = s.v_order, t.v_order = s.u_order, t.u_count = s.v_count, t.v_count = s.u_count;
  t.u_knots = s.v_knots, t.v_knots = s.u_knots;
  t.points.resize(s.points.size());
  if (s.is_rational()) t.weights.resize(s.weights.size());
  for (int j = 0; j < s.v_count; ++j)
    for (int i = 0; i < s.u_count; ++i) {
      t.points[t.index(j, i)] = s.point(i, j);
      if (s.is_rational()) t.weights[t.index(j, i)] = s.weight(i, j);
    }
  return t;
}

// Largest kink jump among the kinks strictly inside a cell of the uniform grid of n steps on [a, b]
// (a kink on a grid line is never straddled).
double straddled_jump(const std::vector<Kink>& kinks, double a, double b, int n) {
  double jump = 0.0;
  const double h = (b - a) / n;
  for (const auto& k : kinks) {
    const double steps = (k.at - a) / h;
    if (std::abs(steps - std::round(steps)) > 1e-9 * std::max(1.0, std::abs(steps))) jump = std::max(jump, k.jump);
  }
  return jump;
}

struct SurfaceModel {
  double du = 0, dv = 0, u0 = 0, v0 = 0;
  SecondDerivativeBound m;
  double speed = 0;  // the largest |S_u|, |S_v|
  std::vector<Kink> kinks_u, kinks_v;

  double deviation(int nu, int nv) const {
    const double hu = du / nu, hv = dv / nv;
    return 0.125 * (hu * hu * m.uu + 2 * hu * hv * m.uv + hv * hv * m.vv) +
           0.25 * hu * straddled_jump(kinks_u, u0, u0 + du, nu) + 0.25 * hv * straddled_jump(kinks_v, v0, v0 + dv, nv);
  }
};

// The grid model of `surface`: the largest sampled normal curvatures and speeds over its Bezier patches
// (the tessellator's own sampling, sample_patch_curvature.hpp) and the kinks bounded from the control net.
SurfaceModel surface_model(const NurbsSurface& surface) {
  SurfaceModel model;
  model.u0 = surface.u_start(), model.v0 = surface.v_start();
  model.du = surface.u_end() - model.u0, model.dv = surface.v_end() - model.v0;
  const SurfaceEvaluator evaluator(surface);
  const std::vector<double> ub = domain_breaks(surface.u_knots, surface.u_order, surface.u_count);
  const std::vector<double> vb = domain_breaks(surface.v_knots, surface.v_order, surface.v_count);
  for (size_t j = 0; j + 1 < vb.size(); ++j)
    for (size_t i = 0; i + 1 < ub.size(); ++i) {
      const tessellation::PatchCurvature k =
          tessellation::sample_patch_curvature(evaluator, ub[i], ub[i + 1], vb[j], vb[j + 1]);
      model.m.uu = std::max(model.m.uu, k.uu);
      model.m.uv = std::max(model.m.uv, k.uv);
      model.m.vv = std::max(model.m.vv, k.vv);
      model.speed = std::max({model.speed, k.su, k.sv});
    }
  model.kinks_u = surface_kinks_u(surface);
  if (!c0_knots(surface.v_knots, surface.v_order, surface.v_count).empty())
    model.kinks_v = surface_kinks_u(transposed(surface));
  return model;
}

// Second-derivative bound of a 2D/3D curve per Bézier segment, and its kinks (exact jumps: the curve
// passes through one point there).
struct CurveModel {
  double a = 0, b = 0, m2 = 0;
  std::vector<Kink> kinks;

  double deviation(int n) const {
    const double h = (b - a) / n;
    return 0.125 * h * h * m2 + 0.25 * h * straddled_jump(kinks, a, b, n);
  }
};

CurveModel curve_model(const NurbsCurve& curve) {
  CurveModel model;
  model.a = curve.domain_start(), model.b = curve.domain_end();
  const int p = curve.degree();
  const auto segments = bezier_segments(curve);
  for (const auto& piece : refined_pieces(segments)) model.m2 = std::max(model.m2, segment_bounds(piece).uu);
  // Only where the curve is C0 (multiplicity >= degree): elsewhere the pieces join with C1.
  const std::vector<double> corners = c0_knots(curve.knots, curve.order, curve.count());
  for (size_t s = 0; s + 1 < segments.size(); ++s) {
    const NurbsCurve& left = segments[s];
    const NurbsCurve& right = segments[s + 1];
    const double k = left.domain_end();
    if (!std::binary_search(corners.begin(), corners.end(), k)) continue;
    const Eigen::Vector4d dl = p / (left.domain_end() - left.domain_start()) *
                               (homogeneous(left.points[p], left.weight(p)) - homogeneous(left.points[p - 1], left.weight(p - 1)));
    const Eigen::Vector4d dr = p / (right.domain_end() - right.domain_start()) *
                               (homogeneous(right.points[1], right.weight(1)) - homogeneous(right.points[0], right.weight(0)));
    const Eigen::Vector4d d = dr - dl;
    const double jump = (d.head<3>() - d[3] * right.points[0]).norm() / right.weight(0);
    if (jump > 1e-12 * (1.0 + right.points[0].norm())) model.kinks.push_back({k, jump});
  }
  return model;
}

// The smallest n in [1, cap] with deviation(n) <= target; cap when none.
template <class Deviation>
int smallest_count(Deviation deviation, double target, int cap) {
  for (int n = 1; n <= cap; ++n)
    if (deviation(n) <= target) return n;
  return cap;
}

}  // namespace

double uniform_chord_deviation_bound(const NurbsCurve& curve, int n) { return curve_model(curve).deviation(std::max(1, n)); }

TessellationHints plan_tessellation_hints(const TrimmedSurface& face, double deviation) {
  if (!(deviation > 0.0) || !std::isfinite(deviation))
    throw std::invalid_argument("plan_tessellation_hints: deviation must be positive and finite");
  TessellationHints hints;
  const NurbsSurface& s = face.surface;
  const SurfaceModel model = surface_model(s);
  // Sampled curvatures: aimed below D by the planning margin.
  const double target = tessellation::kPlanningMargin * deviation;
  const int def_u = 2 * s.u_count, def_v = 2 * s.v_count;
  if (model.deviation(def_u, def_v) > target) {
    const int cap = kMaxSurfaceTessellation;
    int best_u = cap, best_v = cap;
    long best = std::numeric_limits<long>::max();
    for (int nu = 1; nu <= cap; ++nu) {
      const int nv = smallest_count([&](int n) { return model.deviation(nu, n); }, target, cap);
      if (model.deviation(nu, nv) > target) continue;
      const long cells = static_cast<long>(nu) * nv;
      if (cells < best || (cells == best && nu + nv < best_u + best_v)) best = cells, best_u = nu, best_v = nv;
    }
    if (best == std::numeric_limits<long>::max()) {
      // Out of reach within the cap: the cap where it helps, the fewest steps where it does not.
      const double at_cap = model.deviation(cap, cap);
      best_u = smallest_count([&](int n) { return model.deviation(n, cap); }, at_cap * (1 + 1e-12), cap);
      best_v = smallest_count([&](int n) { return model.deviation(best_u, n); }, at_cap * (1 + 1e-12), cap);
    }
    hints.u = best_u == def_u ? 0 : best_u;
    hints.v = best_v == def_v ? 0 : best_v;
  }
  // Trimming chords: (u,v) error e moves the surface point by <= sqrt(2) L |e| (L sampled, so the
  // same margin).
  const double l = model.speed;
  const double uv_target = l > 0.0 ? target / (std::sqrt(2.0) * l) : std::numeric_limits<double>::infinity();
  for (const auto& loop : face.loops) {
    std::vector<int> counts;
    for (const auto& segment : loop.segments) {
      const auto* curve = std::get_if<NurbsCurve>(&segment);
      if (!curve) {
        counts.push_back(0);
        continue;
      }
      const CurveModel cm = curve_model(*curve);
      if (cm.deviation(2 * curve->count()) <= uv_target) {
        counts.push_back(0);
        continue;
      }
      const int n = smallest_count([&](int k) { return cm.deviation(k); }, uv_target, kMaxTrimTessellation);
      counts.push_back(n == 2 * curve->count() ? 0 : n);
    }
    hints.trim_segments.push_back(std::move(counts));
  }
  return hints;
}

}  // namespace cadnurbs
