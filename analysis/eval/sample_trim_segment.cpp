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
// largest sampled distance of criterion (1) (0 when it passed and (2) failed).
bool chord_ok(const SurfaceEvaluator& surface, const SurfaceDeviationBound& bound, const TrimSegment& segment,
              const TrimSample& a, const TrimSample& b, double d, double* sagitta = nullptr) {
  double largest = 0;
  for (int j = 1; j < kChordSamples; ++j) {
    const Eigen::Vector2d uv = segment_uv(segment, a.t + (b.t - a.t) * j / kChordSamples);
    largest = std::max(largest, point_segment_distance(surface.point(uv.x(), uv.y()), a.point, b.point));
  }
  if (sagitta) *sagitta = largest > 0.9 * d ? largest : 0.0;
  if (largest > 0.9 * d) return false;
  return surface_chord_within(surface, bound, a.uv, a.point, b.uv, b.point, d);
}

// Pieces a failed chord is split into: a sagitta grows with the square of the chord, so sqrt(s / 0.9 D)
// pieces would just pass where the curvature is even; 10 % more for arcs of a large angle (where the
// square law underestimates) and at least 2. Bisection alone gives chords of a quarter to all of D, up
// to twice the chords a circle needs.
int pieces_for(double sagitta, double d) {
  if (!(sagitta > 0)) return 2;
  return std::clamp(static_cast<int>(std::ceil(1.1 * std::sqrt(sagitta / (0.9 * d)))), 2, 64);
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
  std::vector<double> breaks = segment_kinks(segment);
  const double t0 = breaks.front(), t1 = breaks.back();
  const double min_step = 1e-12 * std::max(1.0, std::abs(t1 - t0));
  auto sample = [&](double t) {
    const Eigen::Vector2d uv = segment_uv(segment, t);
    return TrimSample{t, uv, surface.point(uv.x(), uv.y())};
  };
  std::vector<TrimSample> out;
  TrimSample first = sample(t0);
  first.point = start_point;
  out.push_back(first);
  for (size_t i = 0; i + 1 < breaks.size(); ++i) {
    const size_t first_of_piece = out.size() - 1;
    TrimSample last = sample(breaks[i + 1]);
    if (i + 2 == breaks.size()) last.point = end_point;
    // Depth-first bisection; `pending` holds the right ends still to reach, nearest last.
    std::vector<TrimSample> pending{last};
    while (!pending.empty()) {
      const TrimSample& a = out.back();
      const TrimSample b = pending.back();
      const bool coarse = too_coarse(a, b);
      double sagitta = 0;
      if (b.t - a.t <= min_step || (!coarse && chord_ok(surface, bound, segment, a, b, max_deviation, &sagitta))) {
        out.push_back(b);
        pending.pop_back();
      } else {
        const int n = coarse ? 2 : pieces_for(sagitta, max_deviation);
        const double ta = a.t, tb = b.t;
        for (int k = n - 1; k >= 1; --k) pending.push_back(sample(ta + (tb - ta) * k / n));
      }
    }
    // Splitting stops at chords anywhere below the deviation allowed. Greedily, each kept sample
    // reaches the farthest later sample whose chord still passes.
    std::vector<TrimSample> merged(out.begin() + static_cast<std::ptrdiff_t>(first_of_piece), out.end());
    out.resize(first_of_piece);
    size_t k = 0;
    out.push_back(merged[0]);
    while (k + 1 < merged.size()) {
      size_t j = k + 1;
      while (j + 1 < merged.size()) {
        const TrimSample& a = out.back();
        const TrimSample& b = merged[j + 1];
        if (too_coarse(a, b) || !chord_ok(surface, bound, segment, a, b, max_deviation)) break;
        ++j;
      }
      out.push_back(merged[j]);
      k = j;
    }
  }
  return out;
}

}  // namespace cadnurbs
