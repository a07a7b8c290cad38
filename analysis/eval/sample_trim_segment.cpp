#include "analysis/eval/sample_trim_segment.hpp"

#include <algorithm>
#include <cmath>

#include "core/point_triangle_distance.hpp"

namespace cadnurbs {

int lines_between(const std::vector<double>& lines, double a, double b) {
  const double lo = std::min(a, b), hi = std::max(a, b);
  return static_cast<int>(std::lower_bound(lines.begin(), lines.end(), hi) - std::upper_bound(lines.begin(), lines.end(), lo));
}

bool is_degenerate_segment(const SurfaceEvaluator& surface, const TrimSegment& segment, double tolerance) {
  const auto breaks = segment_breaks(segment);
  const Eigen::Vector3d first = surface.point(segment_uv(segment, breaks.front()).x(), segment_uv(segment, breaks.front()).y());
  for (size_t i = 0; i + 1 < breaks.size(); ++i)
    for (int k = 0; k <= 8; ++k) {
      const Eigen::Vector2d uv = segment_uv(segment, breaks[i] + (breaks[i + 1] - breaks[i]) * k / 8.0);
      if ((surface.point(uv.x(), uv.y()) - first).norm() > tolerance) return false;
    }
  return true;
}

namespace {

constexpr int kChordSamples = 8;

// Whether chord (a, b) is fine; see the header for the two criteria. `sagitta`, when given, gets the
// largest sampled distance of criterion (1) (up to the first sample over 0.9 D). The pcurve's kinks
// (sorted) inside the chord are sampled too: the even samples can miss a corner.
constexpr double kMaxBulge = 0.3;
constexpr double kNoBulge = 1e-9;

bool chord_ok(const SurfaceEvaluator& surface, const SurfaceDeviationBound& bound, const TrimSegment& segment,
              const std::vector<double>& kinks, const TrimSample& a, const TrimSample& b, double d,
              double* sagitta = nullptr) {
  double largest = 0;
  auto at = [&](double t) {
    const Eigen::Vector2d uv = segment_uv(segment, t);
    largest = std::max(largest, point_segment_distance(surface.point(uv.x(), uv.y()), a.point, b.point));
  };
  for (int j = 1; j < kChordSamples; ++j) at(a.t + (b.t - a.t) * j / kChordSamples);
  for (auto k = std::upper_bound(kinks.begin(), kinks.end(), a.t); k != kinks.end() && *k < b.t && largest <= 0.9 * d; ++k)
    at(*k);
  if (sagitta) *sagitta = largest;
  if (largest > 0.9 * d) return false;
  // Nor does a chord stand for an arc turning by more than about 100 degrees (sagitta above 0.3 of the
  // chord), however coarse D: the two half-cylinders of a lead thinner than D would mesh to one flat quad,
  // its edges used four times (KiCad's R_Axial_Power leads at D = 0.01 x the diagonal). A sagitta below
  // kNoBulge D is rounding, not an arc: where the image stands still (a stretch of a boundary whose control
  // points coincide, robot_jme2.x3dv) every chord is a few ulps long and would be split without end.
  if (largest > kNoBulge * d && largest > kMaxBulge * (b.point - a.point).norm()) return false;
  return surface_chord_within(surface, bound, a.uv, a.point, b.uv, b.point, d);
}

// The n - 1 parameters splitting (ta, tb) evenly, each moved to the nearest kink within half a piece
// (a corner kept as a sample is a chord end, not a chord's middle), sorted and distinct.
std::vector<double> split_parameters(double ta, double tb, int n, const std::vector<double>& kinks) {
  std::vector<double> out;
  const double half = 0.5 * (tb - ta) / n;
  for (int k = 1; k < n; ++k) {
    double t = ta + (tb - ta) * k / n;
    auto it = std::lower_bound(kinks.begin(), kinks.end(), t);
    double best = t, gap = half;
    if (it != kinks.end() && *it < tb && *it - t < gap) best = *it, gap = *it - t;
    if (it != kinks.begin() && *std::prev(it) > ta && t - *std::prev(it) < gap) best = *std::prev(it);
    if (out.empty() || best > out.back()) out.push_back(best);
  }
  return out;
}

// Adds to the sorted `kinks` where a polyline crosses a knot line of the surface that may be only C0:
// the 3D image has a corner there too.
void surface_kink_crossings(const TrimSegment& segment, const SurfaceDeviationBound& bound, std::vector<double>& kinks) {
  const auto* polyline = std::get_if<Polyline2D>(&segment);
  if (!polyline || (bound.c0_u.empty() && bound.c0_v.empty())) return;
  const auto& p = polyline->points;
  for (size_t i = 0; i + 1 < p.size(); ++i)
    for (int axis = 0; axis < 2; ++axis) {
      const double a = p[i][axis], b = p[i + 1][axis];
      for (double line : axis == 0 ? bound.c0_u : bound.c0_v)
        if ((a < line && line < b) || (b < line && line < a)) kinks.push_back(static_cast<double>(i) + (line - a) / (b - a));
    }
  std::sort(kinks.begin(), kinks.end());
  kinks.erase(std::unique(kinks.begin(), kinks.end()), kinks.end());
}

// Pieces a failed chord is split into: a sagitta grows with the square of the chord, so sqrt(s / 0.9 D)
// pieces would just pass where the curvature is even; 10 % more for arcs of a large angle (where the
// square law underestimates) and at least 2. Bisection alone gives chords of a quarter to all of D, up
// to twice the chords a circle needs.
int pieces_for(double sagitta, double d) {
  if (!(sagitta > 0)) return 2;
  return std::clamp(static_cast<int>(std::ceil(1.1 * std::sqrt(sagitta / (0.9 * d)))), 2, 64);
}

// Chords come out uneven (a curvature that varies, split pieces that fell unluckily). Between two
// samples on kinks (corners stay), the chords a run needs is about sum sqrt(s_i / s_max) by the square
// law of sagittas; that many chords (else one more, up to one fewer than the run has) placed so that
// each gets an equal share of sum sqrt(s_i) replace the run when every one of them passes.
template <class Sample, class Passes>
std::vector<TrimSample> evened_runs(const std::vector<TrimSample>& out, const std::vector<double>& sagittas,
                                    const std::vector<double>& kinks, double s_max, Sample sample, Passes passes) {
  std::vector<TrimSample> evened{out.front()};
  for (size_t run_start = 0; run_start + 1 < out.size();) {
    size_t run_end = run_start + 1;
    while (run_end + 1 < out.size() && !std::binary_search(kinks.begin(), kinks.end(), out[run_end].t)) ++run_end;
    const size_t chords = run_end - run_start;
    std::vector<double> share{0.0};  // cumulative sqrt(s_i) over the run's chords
    for (size_t k = run_start; k < run_end; ++k) share.push_back(share.back() + std::sqrt(std::max(sagittas[k], 0.0)));
    const double total = share.back();
    const size_t needed = std::max<size_t>(1, static_cast<size_t>(std::ceil(total / std::sqrt(s_max))));
    std::vector<TrimSample> best(out.begin() + static_cast<std::ptrdiff_t>(run_start) + 1, out.begin() + static_cast<std::ptrdiff_t>(run_end) + 1);
    for (size_t n = needed; n < chords; ++n) {
      std::vector<TrimSample> candidate;
      TrimSample previous = out[run_start];
      bool ok = true;
      size_t c = 0;  // the run's chord holding the k-th share (the shares grow with k)
      for (size_t k = 1; ok && k <= n; ++k) {
        const double fraction = static_cast<double>(k) / static_cast<double>(n);
        TrimSample next = out[run_end];
        if (k < n && total > 0) {
          const double target = total * static_cast<double>(k) / static_cast<double>(n);
          while (c + 1 < chords && share[c + 1] <= target) ++c;
          const double w = share[c + 1] - share[c];
          const double f = w > 0 ? (target - share[c]) / w : 0.0;
          next = sample(out[run_start + c].t + f * (out[run_start + c + 1].t - out[run_start + c].t));
        } else if (k < n) {  // a straight run: evenly in t
          next = sample(out[run_start].t + fraction * (out[run_end].t - out[run_start].t));
        }
        ok = passes(previous, next);
        candidate.push_back(next);
        previous = next;
      }
      if (ok) {
        best = std::move(candidate);
        break;
      }
    }
    evened.insert(evened.end(), best.begin(), best.end());
    run_start = run_end;
  }
  return evened;
}

}  // namespace

bool surface_chord_within(const SurfaceEvaluator& surface, const SurfaceDeviationBound& bound, const Eigen::Vector2d& a_uv,
                          const Eigen::Vector3d& a, const Eigen::Vector2d& b_uv, const Eigen::Vector3d& b, double d) {
  constexpr int m = kChordSamples;
  double parametric = 0;
  for (int j = 1; j < m; ++j) {
    const double s = static_cast<double>(j) / m;
    const Eigen::Vector2d chord_uv = (1 - s) * a_uv + s * b_uv;
    parametric = std::max(parametric, point_segment_distance(surface.point(chord_uv.x(), chord_uv.y()), a, b));
    if (parametric > d) return false;
  }
  // Remainder between the samples of the (u,v) chord: 1D FMM bound on pieces of length h/m.
  const Eigen::Vector2d duv = b_uv - a_uv;
  const auto m2 = bound.over(std::min(a_uv.x(), b_uv.x()), std::max(a_uv.x(), b_uv.x()), std::min(a_uv.y(), b_uv.y()),
                             std::max(a_uv.y(), b_uv.y()));
  const double q = m2.uu * duv.x() * duv.x() + 2 * m2.uv * std::abs(duv.x() * duv.y()) + m2.vv * duv.y() * duv.y();
  // A chord that crosses a C0 knot line has no such bound: the samples are all we have there, and
  // the 3D criterion of the loop sampling keeps such chords short.
  return parametric + q / (8.0 * m * m) <= d;
}

std::vector<TrimSample> sample_trim_segment(const SurfaceEvaluator& surface, const SurfaceDeviationBound& bound,
                                            const TrimSegment& segment, double max_deviation,
                                            const Eigen::Vector3d& start_point, const Eigen::Vector3d& end_point,
                                            const std::vector<double>* grid_u, const std::vector<double>* grid_v) {
  // A chord crossing more than one grid line in u or in v is refused whatever its deviation.
  auto too_coarse = [&](const TrimSample& a, const TrimSample& b) {
    auto crossings = [](const std::vector<double>* g, double x, double y) { return g ? lines_between(*g, x, y) : 0; };
    return crossings(grid_u, a.uv.x(), b.uv.x()) > 1 || crossings(grid_v, a.uv.y(), b.uv.y()) > 1;
  };
  // Chords may span the pcurve's C0 knots (a degree-1 pcurve is all kinks): chord_ok samples them.
  std::vector<double> kinks = segment_kinks(segment);
  const double t0 = kinks.front(), t1 = kinks.back();
  kinks = std::vector<double>(kinks.begin() + 1, kinks.end() - 1);
  surface_kink_crossings(segment, bound, kinks);
  const double min_step = 1e-12 * std::max(1.0, std::abs(t1 - t0));
  auto sample = [&](double t) {
    const Eigen::Vector2d uv = segment_uv(segment, t);
    return TrimSample{t, uv, surface.point(uv.x(), uv.y())};
  };
  TrimSample first = sample(t0);
  first.point = start_point;
  TrimSample last = sample(t1);
  last.point = end_point;
  // Depth-first splitting; `pending` holds the right ends still to reach, nearest last.
  std::vector<TrimSample> split{first};
  std::vector<double> split_sagittas;  // of the chords between split samples
  std::vector<TrimSample> pending{last};
  while (!pending.empty()) {
    const TrimSample& a = split.back();
    const TrimSample b = pending.back();
    const bool coarse = too_coarse(a, b);
    double sagitta = 0;
    if (b.t - a.t <= min_step || (!coarse && chord_ok(surface, bound, segment, kinks, a, b, max_deviation, &sagitta))) {
      split.push_back(b);
      split_sagittas.push_back(sagitta);
      pending.pop_back();
    } else {
      const int n = coarse || sagitta <= 0.9 * max_deviation ? 2 : pieces_for(sagitta, max_deviation);
      const auto ts = split_parameters(a.t, b.t, n, kinks);
      for (auto t = ts.rbegin(); t != ts.rend(); ++t) pending.push_back(sample(*t));
    }
  }
  // Splitting stops at chords anywhere below the deviation allowed, down to a quarter of it when the
  // pieces fall unluckily. Greedily, each chord reaches the farthest later sample whose chord still
  // passes.
  auto passes = [&](const TrimSample& a, const TrimSample& b, double* sagitta = nullptr) {
    return !too_coarse(a, b) && chord_ok(surface, bound, segment, kinks, a, b, max_deviation, sagitta);
  };
  std::vector<TrimSample> out{split[0]};
  std::vector<double> sagittas;  // of out's chords
  for (size_t j = 0; j + 1 < split.size();) {
    double sagitta = split_sagittas[j++];  // out.back() is split[j]: this chord passed in the splitting
    for (double longer = 0; j + 1 < split.size() && passes(out.back(), split[j + 1], &longer); ++j) sagitta = longer;
    out.push_back(split[j]);
    sagittas.push_back(sagitta);
  }
  // Re-placed chords aim at 0.7 D, not the 0.9 D allowed: chords at the limit leave the triangles along
  // them no slack, and their certification cost more than the samples saved (bench_tessellation).
  return evened_runs(out, sagittas, kinks, 0.7 * max_deviation, sample, passes);
}

}  // namespace cadnurbs
