#include "analysis/fitting/fit_position_path.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "analysis/fitting/fit_curve.hpp"
#include "core/bezier_extraction.hpp"
#include "core/geometry_error.hpp"
#include "core/knot_insertion.hpp"
#include "core/number_format.hpp"

namespace cadnurbs {

namespace {

const char* const kEntity = "PositionInterpolator";

void check_path(const std::vector<double>& keys, const std::vector<Eigen::Vector3d>& values) {
  if (keys.empty()) throw GeometryError(kEntity, "no keys");
  if (keys.size() != values.size())
    throw GeometryError(kEntity, std::to_string(keys.size()) + " keys but " + std::to_string(values.size()) +
                                     " key values");
  for (size_t i = 0; i < keys.size(); ++i) {
    if (!std::isfinite(keys[i]) || !values[i].allFinite())
      throw GeometryError(kEntity, "key " + std::to_string(i) + " is not a finite number");
    if (keys[i] < 0 || keys[i] > 1)
      throw GeometryError(kEntity, "key " + std::to_string(i) + " (" + message_number(keys[i]) + ") is outside [0, 1]");
    if (i > 0 && keys[i] < keys[i - 1])
      throw GeometryError(kEntity, "key " + std::to_string(i) + " is smaller than the key before it");
  }
}

// f(t) as approached from the left (`from_left`) or the right: the first value before the first key, the
// last after the last, linear between keys. At a repeated key (a jump) the two differ: from the left the
// run's first value, from the right its last.
Eigen::Vector3d path_point(const std::vector<double>& keys, const std::vector<Eigen::Vector3d>& values, double t,
                           bool from_left) {
  if (t < keys.front() || (t == keys.front() && from_left)) return values.front();
  if (t > keys.back() || (t == keys.back() && !from_left)) return values.back();
  if (from_left) {
    const size_t i = std::lower_bound(keys.begin(), keys.end(), t) - keys.begin();  // keys[i-1] < t <= keys[i]
    if (keys[i] == t) return values[i];
    const double s = (t - keys[i - 1]) / (keys[i] - keys[i - 1]);
    return (1 - s) * values[i - 1] + s * values[i];
  }
  const size_t i = std::upper_bound(keys.begin(), keys.end(), t) - keys.begin();  // keys[i-1] <= t < keys[i]
  if (keys[i - 1] == t) return values[i - 1];
  const double s = (t - keys[i - 1]) / (keys[i] - keys[i - 1]);
  return (1 - s) * values[i - 1] + s * values[i];
}

// `piece`, clamped on [t0, t1], joined to constant pieces on [0, t0] and [t1, 1] (a knot of multiplicity
// order - 1 at each join, the extra control points equal to the end point).
NurbsCurve with_constant_ends(const NurbsCurve& piece, double t0, double t1) {
  const int k = piece.order;
  NurbsCurve curve = piece;
  if (t0 > 0) {
    std::vector<double> knots(k, 0.0);
    knots.insert(knots.end(), k - 1, t0);
    knots.insert(knots.end(), curve.knots.begin() + k, curve.knots.end());
    curve.knots = std::move(knots);
    curve.points.insert(curve.points.begin(), k - 1, curve.points.front());
  }
  if (t1 < 1) {
    curve.knots.resize(curve.knots.size() - k);
    curve.knots.insert(curve.knots.end(), k - 1, t1);
    curve.knots.insert(curve.knots.end(), k, 1.0);
    curve.points.insert(curve.points.end(), k - 1, curve.points.back());
  }
  return curve;
}

NurbsCurve constant_curve(const Eigen::Vector3d& value) {
  NurbsCurve curve;
  curve.order = 2;
  curve.knots = {0, 0, 1, 1};
  curve.points = {value, value};
  return curve;
}

}  // namespace

double path_error_bound(const NurbsCurve& curve, const std::vector<double>& keys,
                        const std::vector<Eigen::Vector3d>& values) {
  check_path(keys, values);
  if (curve.is_rational()) throw GeometryError(kEntity, "the path error bound is for polynomial curves");
  std::vector<double> cuts;
  for (double key : keys)
    if (key > curve.domain_start() && key < curve.domain_end() &&
        !std::binary_search(curve.knots.begin(), curve.knots.end(), key) && (cuts.empty() || cuts.back() != key))
      cuts.push_back(key);
  const NurbsCurve refined = cuts.empty() ? curve : refine_knots(curve, cuts);
  double bound = 0;
  for (const NurbsCurve& piece : bezier_segments(refined)) {
    const double a = piece.knots.front(), b = piece.knots.back();
    const Eigen::Vector3d fa = path_point(keys, values, a, false), fb = path_point(keys, values, b, true);
    const int degree = piece.degree();
    for (int j = 0; j <= degree; ++j) {
      const Eigen::Vector3d line_point = fa + (double(j) / degree) * (fb - fa);
      bound = std::max(bound, (piece.points[j] - line_point).norm());
    }
  }
  return bound;
}

namespace {

// One stretch of the path between jumps, its near-repeated keys merged: fitted alone.
struct PathStretch {
  std::vector<double> keys;
  std::vector<Eigen::Vector3d> values;
};

// The path cut at its jumps (a key repeated with values at least `deviation` apart); a key repeated with
// closer values (keys written with few decimals) is one key at the values' midpoint. Stretches of one key
// (between two jumps at one fraction) are dropped: no fraction is theirs.
std::vector<PathStretch> stretches_of(const std::vector<double>& keys, const std::vector<Eigen::Vector3d>& values,
                                      double deviation) {
  std::vector<PathStretch> out(1);
  for (size_t i = 0; i < keys.size();) {
    size_t j = i;
    while (j + 1 < keys.size() && keys[j + 1] == keys[i]) ++j;
    if ((values[j] - values[i]).norm() >= deviation) {  // a jump: the left value ends a stretch
      out.back().keys.push_back(keys[i]);
      out.back().values.push_back(values[i]);
      out.emplace_back();
      out.back().keys.push_back(keys[j]);
      out.back().values.push_back(values[j]);
    } else {
      out.back().keys.push_back(keys[i]);
      out.back().values.push_back(0.5 * (values[i] + values[j]));
    }
    i = j + 1;
  }
  std::erase_if(out, [](const PathStretch& s) { return s.keys.size() < 2; });
  return out;
}

// A curve clamped on [0, 1] within `tolerance` of the stretch's samples (its keys and the points halfway,
// and quarter points where the stretch has too few keys for the order), ends on its first and last values.
NurbsCurve fit_stretch(const PathStretch& s, double tolerance, int order, int& sample_count) {
  const double t0 = s.keys.front(), t1 = s.keys.back();
  const int keys = static_cast<int>(s.keys.size());
  const int between = 2 * keys - 1 >= order + 1 ? 2 : 4;  // samples per gap: enough for the order
  CurveSamples samples;
  for (size_t i = 0; i < s.keys.size(); ++i) {
    if (i > 0)
      for (int k = 1; k < between; ++k) {
        const double f = double(k) / between;
        samples.parameters.push_back(((1 - f) * s.keys[i - 1] + f * s.keys[i] - t0) / (t1 - t0));
        samples.points.push_back((1 - f) * s.values[i - 1] + f * s.values[i]);
      }
    samples.parameters.push_back(i + 1 == s.keys.size() ? 1.0 : (s.keys[i] - t0) / (t1 - t0));
    samples.points.push_back(s.values[i]);
  }
  sample_count += static_cast<int>(samples.parameters.size());
  CurveFitOptions options;
  options.order = order;
  options.optimise_weights = false;
  CurveFit fitted;
  try {
    fitted = fit_curve_within(samples, tolerance, options);
  } catch (const std::invalid_argument& e) {  // the data cannot be met with fewer control points
    throw GeometryError(kEntity, e.what());
  }
  // The ends on the stretch's first and last values exactly, so an animation starts and stops (and jumps)
  // where the original does: a clamped curve passes through its end points, and moving one moves the
  // curve by at most that much (the bound is taken afterwards).
  fitted.curve.points.front() = s.values.front();
  fitted.curve.points.back() = s.values.back();
  // Onto [t0, t1], its ends the keys' own bits (a jump's knot is then the key exactly).
  for (double& knot : fitted.curve.knots) knot = t0 + knot * (t1 - t0);
  std::fill(fitted.curve.knots.begin(), fitted.curve.knots.begin() + order, t0);
  std::fill(fitted.curve.knots.end() - order, fitted.curve.knots.end(), t1);
  return fitted.curve;
}

// Curves clamped on consecutive ranges joined into one: the knot where they meet gets full multiplicity
// (order), so the curve may jump there, each side keeping its own end point.
NurbsCurve joined(const std::vector<NurbsCurve>& pieces) {
  NurbsCurve out = pieces.front();
  for (size_t i = 1; i < pieces.size(); ++i) {
    const NurbsCurve& p = pieces[i];
    out.points.insert(out.points.end(), p.points.begin(), p.points.end());
    out.knots.insert(out.knots.end(), p.knots.begin() + p.order, p.knots.end());
  }
  return out;
}

}  // namespace

PositionPathFit fit_position_path(const std::vector<double>& keys, const std::vector<Eigen::Vector3d>& values,
                                  double deviation, const CurveAsWritten& as_written) {
  check_path(keys, values);
  if (!(deviation > 0)) throw GeometryError(kEntity, "the deviation must be > 0");
  const auto written = [&](const NurbsCurve& curve) { return as_written ? as_written(curve) : curve; };
  const std::vector<PathStretch> stretches = stretches_of(keys, values, deviation);
  if (stretches.empty()) {  // every key at one fraction, or every value within D of one point
    PositionPathFit fit;
    fit.curve = constant_curve(values.front());
    fit.max_error = path_error_bound(written(fit.curve), keys, values);
    return fit;
  }
  int distinct_keys = 0;
  for (const auto& s : stretches) distinct_keys += static_cast<int>(s.keys.size());
  const int order = std::min(4, std::max(2, distinct_keys));
  const double t0 = stretches.front().keys.front(), t1 = stretches.back().keys.back();

  // The fit's tolerance leaves room for the written numbers' rounding; tightened when the bound of the
  // written curve still exceeds the deviation (the fit meets its tolerance at the samples only). The bound
  // is taken against the path as given: a merged near-repeat counts with its own two values.
  double tolerance = 0.8 * deviation;
  for (int attempt = 0; attempt < 4; ++attempt, tolerance *= 0.5) {
    std::vector<NurbsCurve> pieces;
    int samples = 0;
    for (const auto& s : stretches) pieces.push_back(fit_stretch(s, tolerance, order, samples));
    PositionPathFit fit;
    fit.curve = with_constant_ends(joined(pieces), t0, t1);
    fit.max_error = path_error_bound(written(fit.curve), keys, values);
    fit.fitted_samples = samples;
    if (fit.max_error <= deviation) return fit;
  }
  throw GeometryError(kEntity, "no fitted curve came within " + message_number(deviation) + " of the path");
}

}  // namespace cadnurbs
