#include "analysis/tessellation/grid_planning.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "analysis/tessellation/segment_meets_box.hpp"
#include "analysis/tessellation/sample_patch_curvature.hpp"
#include "core/point_in_loops.hpp"

namespace cadnurbs::tessellation {

namespace {

// Positive root y of q y^2 + c y + r = 0 (r < 0), as a step fraction in (0, 1].
double positive_root(double q, double c, double r) {
  if (q <= 0) return c > 0 ? std::min(1.0, -r / c) : 1.0;
  const double y = (-c + std::sqrt(c * c - 4 * q * r)) / (2 * q);
  return std::clamp(y, 1e-9, 1.0);
}

// Which Bezier patches (i + j * (u_breaks.size() - 1)) the trimmed region reaches: a loop passes
// through the patch's inside, or its centre is inside the loops.
std::vector<char> patches_in_region(const std::vector<double>& ub, const std::vector<double>& vb,
                                    const std::vector<std::vector<Eigen::Vector2d>>& polys) {
  const int nu = static_cast<int>(ub.size()) - 1, nv = static_cast<int>(vb.size()) - 1;
  std::vector<char> used(static_cast<size_t>(nu) * nv, 0);
  PointInLoops region(polys);
  auto cell_of = [](const std::vector<double>& b, double x) {
    const int n = static_cast<int>(b.size()) - 1;
    return std::clamp(static_cast<int>(std::upper_bound(b.begin(), b.end(), x) - b.begin()) - 1, 0, n - 1);
  };
  for (const auto& poly : polys)
    for (size_t k = 0; k < poly.size(); ++k) {
      const Eigen::Vector2d& a = poly[k];
      const Eigen::Vector2d& b = poly[(k + 1) % poly.size()];
      const int i0 = cell_of(ub, std::min(a.x(), b.x())), i1 = cell_of(ub, std::max(a.x(), b.x()));
      const int j0 = cell_of(vb, std::min(a.y(), b.y())), j1 = cell_of(vb, std::max(a.y(), b.y()));
      // The patch's inside, less 1e-9 of it: a loop along its edge (a trim on a knot line, or an ulp past
      // it) does not reach it, for its curvature is not the face's (hammer.iges: 2.2e-15 into a patch 0.003
      // wide whose curvature made the face want 4096 cells across).
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) {
          const double mu = 1e-9 * (ub[i + 1] - ub[i]), mv = 1e-9 * (vb[j + 1] - vb[j]);
          if (segment_meets_box(a, b, ub[i] + mu, ub[i + 1] - mu, vb[j] + mv, vb[j + 1] - mv)) used[i + j * nu] = 1;
        }
    }
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i)
      if (region.inside({0.5 * (ub[i] + ub[i + 1]), 0.5 * (vb[j] + vb[j + 1])})) used[i + j * nu] = 1;
  return used;
}

struct PatchSteps {
  double u, v;  // wanted cells across the patch in u and in v (fractional)
};

// Largest turn of the surface normal across one cell along a straight direction of a twisted surface
// (radians). A cell one step long there is a long thin triangle pair whose plane tilts against the
// surface by up to half the turn: within D of it, but with area (1/cos - 1) too much, +3 % on a
// capacitor's twisted ruled faces. 0.06 keeps that below about 0.05 %.
constexpr double kTwistTurn = 0.06;

// The cells patch [u0, u1] x [v0, v1] wants so that its FMM estimate is `target`, and so that
// along a straight direction of a twisted patch the normal turns by at most kTwistTurn per cell.
PatchSteps patch_steps(const SurfaceEvaluator& e, double u0, double u1, double v0, double v1, double target) {
  const PatchCurvature k = sample_patch_curvature(e, u0, u1, v0, v1);
  const double hu = u1 - u0, hv = v1 - v0;
  const double muu = k.uu, muv = k.uv, mvv = k.vv, turn_u = k.turn_u, turn_v = k.turn_v;
  // One-step errors of the cell in each direction, and the mixed term.
  const double a = muu * hu * hu / 8, b = mvv * hv * hv / 8, c = 2 * muv * hu * hv / 8;
  // Step fractions 1 / n. A patch already within the target may share a cell with its
  // neighbours: x = y > 1 then, and a flat patch wants no cell of its own at all.
  const double whole = a + b + c;
  double x = whole > 0 ? std::sqrt(target / whole) : 1e9, y = x;
  if (whole > target) {
    x = y = 1;
    if (a <= 0 || b <= 0) {
      // One direction is straight: all of the budget to the other.
      if (a > 0) x = positive_root(a, c, b - target);
      if (b > 0) y = positive_root(b, c, a - target);
      if (a <= 0 && c <= 0) x = 1e9;  // straight and untwisted: no need to step at all
      if (b <= 0 && c <= 0) y = 1e9;
      if (a <= 0 && b <= 0) x = y = std::sqrt(target / c);
      // Straight but twisted: the normal's turn bounds the steps along the straight direction; the
      // budget the fewer steps there leave goes to the other one.
      if (b <= 0 && c > 0 && a > 0 && turn_v * hv * y > kTwistTurn) {
        y = kTwistTurn / (turn_v * hv);
        x = positive_root(a, c * y, -target);
      }
      if (a <= 0 && c > 0 && b > 0 && turn_u * hu * x > kTwistTurn) {
        x = kTwistTurn / (turn_u * hu);
        y = positive_root(b, c * x, -target);
      }
    } else {
      const double t2 = target / (2 + c / std::sqrt(a * b));
      x = std::sqrt(t2 / a), y = std::sqrt(t2 / b);
      if (x > 1) x = 1, y = positive_root(b, c, a - target);
      else if (y > 1) y = 1, x = positive_root(a, c, b - target);
    }
  }
  return {std::min(4096.0, 1 / std::max(x, 1e-9)), std::min(4096.0, 1 / std::max(y, 1e-9))};
}

}  // namespace

std::vector<double> graded_grid_lines(const std::vector<double>& b, const std::vector<double>& steps,
                                      const std::vector<double>& hard) {
  std::vector<double> stops{b.front()};
  for (double x : hard)
    if (x > b.front() && x < b.back()) stops.push_back(x);
  stops.push_back(b.back());
  std::vector<double> out{b.front()};
  size_t i = 0;  // span holding the walk
  for (size_t h = 0; h + 1 < stops.size(); ++h) {
    const double from = stops[h], to = stops[h + 1];
    // Cumulative wanted cells at each span end within [from, to].
    std::vector<double> xs{from}, cells{0.0};
    for (size_t k = i; k + 1 < b.size() && b[k] < to; ++k) {
      const double lo = std::max(b[k], from), hi = std::min(b[k + 1], to);
      if (hi <= lo) continue;
      xs.push_back(hi);
      cells.push_back(cells.back() + steps[k] * (hi - lo) / (b[k + 1] - b[k]));
    }
    while (i + 1 < b.size() && b[i + 1] <= to) ++i;
    const int n = std::max(1, static_cast<int>(std::ceil(cells.back() - 1e-9)));
    size_t k = 1;
    for (int line = 1; line < n; ++line) {
      const double target = cells.back() * line / n;
      while (cells[k] < target) ++k;
      const double w = (target - cells[k - 1]) / (cells[k] - cells[k - 1]);
      out.push_back(xs[k - 1] + w * (xs[k] - xs[k - 1]));
    }
    out.push_back(to);
  }
  return out;
}

TessellationGrid plan_tessellation_grid(const SurfaceEvaluator& surface, const SurfaceDeviationBound& bound,
                                        const std::vector<std::vector<Eigen::Vector2d>>& loops, double max_deviation) {
  const auto& ub = bound.u_breaks;
  const auto& vb = bound.v_breaks;
  const int nu = static_cast<int>(ub.size()) - 1, nv = static_cast<int>(vb.size()) - 1;
  const std::vector<char> used = patches_in_region(ub, vb, loops);
  const double target = kPlanningMargin * max_deviation;
  std::vector<double> steps_u(nu, 0.0), steps_v(nv, 0.0);  // wanted cells per span (fractional)
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      if (!used[i + j * nu]) continue;
      const PatchSteps wanted = patch_steps(surface, ub[i], ub[i + 1], vb[j], vb[j + 1], target);
      steps_u[i] = std::max(steps_u[i], wanted.u);
      steps_v[j] = std::max(steps_v[j], wanted.v);
    }
  return {graded_grid_lines(ub, steps_u, bound.c0_u), graded_grid_lines(vb, steps_v, bound.c0_v)};
}

}  // namespace cadnurbs::tessellation
