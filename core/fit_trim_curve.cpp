#include "core/fit_trim_curve.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/geometry_error.hpp"
#include "core/interpolate_curve.hpp"
#include "core/knot_vector.hpp"
#include "core/number_format.hpp"

namespace cadnurbs {

namespace {

constexpr int kMaxRemovalTries = 512;

const char* const kEntity = "trim curve fit";
// Intervals (in s) shorter than this are not bisected: 2^-40, far below any edge's features.
constexpr double kShortestInterval = 0x1p-40;
// A curve whose control points are moved into the domain may leave the edge by this many tolerances
// (KiCad's QFP fillets: 2.5, where the edge itself lies 100 tolerances off the surface).
constexpr double kDomainClampSlack = 4.0;

struct Sample {
  double s;                  // the trim curve's parameter, in [0, 1]
  Eigen::Vector3d point;     // edge(t(s))
  Eigen::Vector2d uv;        // its located (u,v)
  Eigen::Vector3d midpoint;  // the edge point halfway (in s) to the next sample; unused for the last
  Eigen::Vector3d target;           // the surface point at uv: where the image must pass
  Eigen::Vector3d midpoint_target;  // the surface point the midpoint is located at
  bool at_knot = false;      // at an end or a knot of the edge
};

struct Check {
  double max_distance = 0.0;
  double worst_s = 0.0;
  std::vector<char> failed;  // per interval: its midpoint is beyond the tolerance
  bool passed = true;
};

class TrimFitter {
 public:
  TrimFitter(const NurbsCurve& edge, double t0, double t1, const LocateOnSurface& locate, const SurfaceAt& surface_at,
             double tolerance, double off_surface_limit, const std::optional<Eigen::AlignedBox2d>& domain)
      : edge_(edge), t0_(t0), t1_(t1), locate_(locate), surface_at_(surface_at), tolerance_(tolerance),
        off_surface_limit_(off_surface_limit), domain_(domain) {}

  double t_of(double s) const { return s >= 1.0 ? t1_ : t0_ + s * (t1_ - t0_); }
  Eigen::Vector3d edge_at(double s) const { return curve_point(edge_, t_of(s)); }

  // Refuses a (u,v) whose surface point is not within the tolerance of the edge point.
  void require_on_surface(const Eigen::Vector2d& uv, const Eigen::Vector3d& point, double s) const {
    const double d = uv.allFinite() ? (surface_at_(uv) - point).norm() : std::numeric_limits<double>::infinity();
    if (d <= off_surface_limit_) return;
    throw GeometryError(kEntity, "the edge does not lie on the surface: " +
                                     (std::isfinite(d) ? message_number(d) + " from it" : std::string("no finite (u,v)")) +
                                     " at parameter " + message_number(t_of(s)) + " (tolerance " +
                                     message_number(off_surface_limit_) + ")");
  }

  Sample sample(double s, const Eigen::Vector3d& point, const Eigen::Vector2d& previous_uv) const {
    const Eigen::Vector2d uv = locate_(point, previous_uv);
    require_on_surface(uv, point, s);
    return {s, point, uv, Eigen::Vector3d::Zero(), surface_at_(uv), Eigen::Vector3d::Zero()};
  }

  // The midpoint of sample k's interval (in s, to s_next), and the surface point it is located at.
  void set_midpoint(Sample& sample, double s_next) const {
    sample.midpoint = edge_at(0.5 * (sample.s + s_next));
    sample.midpoint_target = surface_at_(locate_(sample.midpoint, sample.uv));
  }

  // The distances of curve c's image at every sample and every midpoint; with `first_failure` it
  // stops at the first one beyond the tolerance (enough to reject a candidate).
  Check check(const NurbsCurve& c, const std::vector<Sample>& samples, bool first_failure) const {
    Check result;
    result.failed.assign(samples.size(), 0);
    auto measure = [&](double s, const Eigen::Vector3d& target) {
      const Eigen::Vector3d uv = curve_point(c, s);
      const double d = (surface_at_(uv.head<2>()) - target).norm();
      if (!(d <= result.max_distance)) result.max_distance = d, result.worst_s = s;
      return d <= tolerance_;
    };
    for (size_t k = 0; k < samples.size(); ++k) {
      if (!measure(samples[k].s, samples[k].target)) result.passed = false;
      if (k + 1 < samples.size() && !measure(0.5 * (samples[k].s + samples[k + 1].s), samples[k].midpoint_target))
        result.failed[k] = 1, result.passed = false;
      if (!result.passed && first_failure) break;
    }
    return result;
  }

  static NurbsCurve fit(const std::vector<Sample>& samples, const std::vector<int>& subset, int degree) {
    std::vector<Eigen::Vector3d> points;
    std::vector<double> parameters;
    for (int k : subset) {
      points.emplace_back(samples[k].uv.x(), samples[k].uv.y(), 0.0);
      parameters.push_back(samples[k].s);
    }
    return interpolate_curve(points, parameters, degree, 2);
  }

  // c with its control points moved into the domain, if one is given and the result stays within
  // kDomainClampSlack tolerances at every check; c otherwise. With its check.
  std::pair<NurbsCurve, Check> within_domain(const NurbsCurve& c, const std::vector<Sample>& samples) const {
    if (domain_) {
      NurbsCurve clamped = c;
      for (auto& p : clamped.points) p.head<2>() = p.head<2>().cwiseMax(domain_->min()).cwiseMin(domain_->max());
      Check checked = check(clamped, samples, false);
      if (checked.max_distance <= kDomainClampSlack * tolerance_) return {std::move(clamped), std::move(checked)};
    }
    return {c, check(c, samples, false)};
  }

  // The samples with a new one at the midpoint of every failed interval.
  std::vector<Sample> bisected(const std::vector<Sample>& samples, const std::vector<char>& failed) const {
    std::vector<Sample> out;
    for (size_t k = 0; k < samples.size(); ++k) {
      out.push_back(samples[k]);
      if (!failed[k]) continue;
      const double s = 0.5 * (samples[k].s + samples[k + 1].s);
      Sample middle = sample(s, samples[k].midpoint, samples[k].uv);
      set_midpoint(out.back(), s);
      set_midpoint(middle, samples[k + 1].s);
      out.push_back(middle);
    }
    return out;
  }

  [[noreturn]] void refuse_fit(const Check& c, size_t samples) const {
    throw GeometryError(kEntity, "trim curve does not follow its edge within " + message_number(tolerance_) +
                                     " after " + std::to_string(samples) + " samples: " +
                                     message_number(c.max_distance) + " at parameter " +
                                     message_number(t_of(c.worst_s)));
  }

 private:
  const NurbsCurve& edge_;
  double t0_, t1_;
  const LocateOnSurface& locate_;
  const SurfaceAt& surface_at_;
  double tolerance_;
  double off_surface_limit_;
  std::optional<Eigen::AlignedBox2d> domain_;
};

void check_input(const NurbsCurve& edge, double t0, double t1, const Eigen::Vector2d& start_uv, double tolerance) {
  validate(edge, "trim curve fit's edge");
  if (edge.dimension != 3) throw GeometryError(kEntity, "the edge curve is 2D; a 3D curve is needed");
  if (!std::isfinite(t0) || !std::isfinite(t1) || !start_uv.allFinite())
    throw GeometryError(kEntity, "non-finite parameter range or start (u,v)");
  if (!(tolerance > 0.0) || !std::isfinite(tolerance))
    throw GeometryError(kEntity, "tolerance " + message_number(tolerance) + " is not a positive number");
  if (t0 == t1) throw GeometryError(kEntity, "empty parameter range at " + message_number(t0));
  const double a = edge.domain_start(), b = edge.domain_end(), slack = 1e-12 * (b - a);
  for (double t : {t0, t1})
    if (t < a - slack || t > b + slack)
      throw GeometryError(kEntity, "parameter " + message_number(t) + " is outside the edge's domain [" +
                                       message_number(a) + ", " + message_number(b) + "]");
}

// The starting samples' s values: per knot span of the edge in the range, max(2, degree + 1) equal
// intervals (at least 4 in all, fewer a span past 256); flags the knots. Ascending, 0 and 1 exact.
std::vector<std::pair<double, bool>> initial_parameters(const NurbsCurve& edge, double t0, double t1) {
  const double lo = std::min(t0, t1), hi = std::max(t0, t1);
  std::vector<double> cuts{lo};
  for (double b : domain_breaks(edge.knots, edge.order, edge.count()))
    if (b > lo && b < hi) cuts.push_back(b);
  cuts.push_back(hi);
  const int spans = static_cast<int>(cuts.size()) - 1;
  // At most ~256 to start with: an edge of hundreds of spans (a dense interpolant) gets one interval
  // a span; bisection adds samples where they are needed.
  int per_span = std::max({2, edge.degree() + 1, (4 + spans - 1) / spans});
  if (spans * per_span > 256) per_span = std::max(1, 256 / spans);
  std::vector<std::pair<double, bool>> s;
  for (int k = 0; k < spans; ++k)
    for (int i = 0; i < per_span; ++i) {
      const double t = cuts[k] + (cuts[k + 1] - cuts[k]) * i / per_span;
      s.emplace_back((t - t0) / (t1 - t0), i == 0);
    }
  s.emplace_back((hi - t0) / (t1 - t0), true);
  std::sort(s.begin(), s.end());
  s.front().first = 0.0, s.back().first = 1.0;
  return s;
}

// Whether every sample's (u,v) lies on the chord's line to 1e-10 of the samples' extent.
bool collinear(const std::vector<Sample>& samples) {
  const Eigen::Vector2d a = samples.front().uv, chord = samples.back().uv - a;
  double extent = 0.0;
  for (const Sample& q : samples) extent = std::max(extent, (q.uv - a).norm());
  if (!(chord.norm() > 0.5 * extent) || extent == 0.0) return false;  // closed or folded back
  const Eigen::Vector2d normal = Eigen::Vector2d(-chord.y(), chord.x()).normalized();
  for (const Sample& q : samples)
    if (std::abs((q.uv - a).dot(normal)) > 1e-10 * extent) return false;
  return true;
}

TrimCurveFit result(const NurbsCurve& curve, const Check& c, const std::vector<Sample>& samples) {
  return {curve, c.max_distance, static_cast<int>(2 * samples.size() - 1)};
}

}  // namespace

TrimCurveFit fit_trim_curve(const NurbsCurve& edge, double t0, double t1, const Eigen::Vector2d& start_uv,
                            const LocateOnSurface& locate, const SurfaceAt& surface_at, double tolerance,
                            double off_surface_limit, const std::optional<Eigen::AlignedBox2d>& domain) {
  check_input(edge, t0, t1, start_uv, tolerance);
  const TrimFitter fitter(edge, t0, t1, locate, surface_at, tolerance,
                          off_surface_limit > 0 ? std::max(off_surface_limit, tolerance) : tolerance, domain);

  std::vector<Sample> samples;
  for (const auto& [s, at_knot] : initial_parameters(edge, t0, t1)) {
    const Eigen::Vector3d point = fitter.edge_at(s);
    if (samples.empty()) {
      fitter.require_on_surface(start_uv, point, s);
      samples.push_back({s, point, start_uv, Eigen::Vector3d::Zero(), surface_at(start_uv), Eigen::Vector3d::Zero()});
    } else {
      samples.push_back(fitter.sample(s, point, samples.back().uv));
    }
    samples.back().at_knot = at_knot;
  }
  for (size_t k = 0; k + 1 < samples.size(); ++k) fitter.set_midpoint(samples[k], samples[k + 1].s);

  // Cheap cases first: a straight image (2 points), a polyline edge's image as a polyline.
  if (collinear(samples)) {
    const NurbsCurve line = TrimFitter::fit(samples, {0, static_cast<int>(samples.size()) - 1}, 1);
    if (const Check c = fitter.check(line, samples, false); c.passed) return result(line, c, samples);
  }
  if (edge.degree() == 1) {
    std::vector<int> knots;
    for (size_t k = 0; k < samples.size(); ++k)
      if (samples[k].at_knot) knots.push_back(static_cast<int>(k));
    const NurbsCurve polyline = TrimFitter::fit(samples, knots, 1);
    if (const Check c = fitter.check(polyline, samples, false); c.passed) return result(polyline, c, samples);
  }

  // Interpolate every sample; bisect the intervals whose midpoints fail, until none does.
  std::vector<int> all;
  NurbsCurve curve;  // the fit within tolerance with the fewest control points so far
  Check checked;
  for (;;) {
    all.resize(samples.size());
    for (size_t k = 0; k < samples.size(); ++k) all[k] = static_cast<int>(k);
    curve = TrimFitter::fit(samples, all, 3);
    checked = fitter.check(curve, samples, false);
    if (checked.passed) break;
    const size_t added = std::count(checked.failed.begin(), checked.failed.end(), 1);
    if (samples.size() + added > static_cast<size_t>(kMaxTrimCurveSamples)) fitter.refuse_fit(checked, samples.size());
    // An interval too short to bisect: the image jumps there (a seam placed wrongly, say).
    for (size_t k = 0; k + 1 < samples.size(); ++k)
      if (checked.failed[k] && samples[k + 1].s - samples[k].s < kShortestInterval)
        fitter.refuse_fit(checked, samples.size());
    samples = fitter.bisected(samples, checked.failed);
  }

  // Fewer control points: drop every other sample while the interpolant of the rest passes every
  // check, then single samples greedily. (Least-squares fits with P&T 9.4.1's knots were tried: they
  // needed more points than this on the oblique ellipse, whose image bends sharply at 8 C1 joints.)
  std::vector<int> kept = all;
  auto try_subset = [&](const std::vector<int>& subset) {
    NurbsCurve candidate = TrimFitter::fit(samples, subset, 3);
    if (!fitter.check(candidate, samples, true).passed) return false;
    kept = subset, curve = std::move(candidate);
    return true;
  };
  while (kept.size() > 2) {
    std::vector<int> halved;
    for (size_t k = 0; k < kept.size(); k += 2) halved.push_back(kept[k]);
    if (halved.back() != kept.back()) halved.push_back(kept.back());
    if (halved.size() == kept.size() || !try_subset(halved)) break;
  }
  // Then runs of samples after each kept one, the run doubling while removals pass and halving when one
  // fails (a fit and a check per try: galloping keeps the tries near one per kept sample, not per sample).
  // At most kMaxRemovalTries tries: on a long wiggly edge (a fuzzed file: 907 samples, 359 kept) the
  // tries are each a fit and a check of every sample; stopping early keeps a few more points.
  int tries = 0;
  for (size_t pos = 1, run = 1; pos + 1 < kept.size() && tries < kMaxRemovalTries; ++tries) {
    const size_t count = std::min(run, kept.size() - 1 - pos);
    std::vector<int> fewer = kept;
    fewer.erase(fewer.begin() + static_cast<long>(pos), fewer.begin() + static_cast<long>(pos + count));
    if (try_subset(fewer)) {
      run *= 2;
    } else if (run > 1) {
      run /= 2;
    } else {
      ++pos;
    }
  }
  // (A line or polyline between located points stays in the domain; an interpolant may overshoot it.)
  const auto [kept_curve, kept_check] = fitter.within_domain(curve, samples);
  return result(kept_curve, kept_check, samples);
}

}  // namespace cadnurbs
