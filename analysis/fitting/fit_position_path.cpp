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
    if (i > 0 && keys[i] == keys[i - 1] && values[i] != values[i - 1])
      throw GeometryError(kEntity, "key " + std::to_string(i) + " repeats the key before it with another value (a jump)");
  }
}

// f(t): the first value before the first key, the last after the last, linear between keys.
Eigen::Vector3d path_point(const std::vector<double>& keys, const std::vector<Eigen::Vector3d>& values, double t) {
  if (t <= keys.front()) return values.front();
  if (t >= keys.back()) return values.back();
  const size_t i = std::upper_bound(keys.begin(), keys.end(), t) - keys.begin();  // keys[i-1] <= t < keys[i]
  const double s = (t - keys[i - 1]) / (keys[i] - keys[i - 1]);
  return (1 - s) * values[i - 1] + s * values[i];
}

// `piece`, clamped on [0, 1], stretched onto [t0, t1] and joined to constant pieces on [0, t0] and [t1, 1]
// (a knot of multiplicity order - 1 at each join, the extra control points equal to the end point).
NurbsCurve with_constant_ends(const NurbsCurve& piece, double t0, double t1) {
  const int k = piece.order;
  NurbsCurve curve = piece;
  for (double& knot : curve.knots) knot = t0 + knot * (t1 - t0);
  std::fill(curve.knots.begin(), curve.knots.begin() + k, t0);
  std::fill(curve.knots.end() - k, curve.knots.end(), t1);
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
    const Eigen::Vector3d fa = path_point(keys, values, a), fb = path_point(keys, values, b);
    const int degree = piece.degree();
    for (int j = 0; j <= degree; ++j) {
      const Eigen::Vector3d line_point = fa + (double(j) / degree) * (fb - fa);
      bound = std::max(bound, (piece.points[j] - line_point).norm());
    }
  }
  return bound;
}

PositionPathFit fit_position_path(const std::vector<double>& keys, const std::vector<Eigen::Vector3d>& values,
                                  double deviation, const CurveAsWritten& as_written) {
  check_path(keys, values);
  if (!(deviation > 0)) throw GeometryError(kEntity, "the deviation must be > 0");
  const auto written = [&](const NurbsCurve& curve) { return as_written ? as_written(curve) : curve; };
  const double t0 = keys.front(), t1 = keys.back();
  if (t0 == t1) {
    PositionPathFit fit;
    fit.curve = constant_curve(values.front());
    fit.max_error = path_error_bound(written(fit.curve), keys, values);
    return fit;
  }

  // Samples on [0, 1] (the stretched [t0, t1]): every distinct key, and the path halfway between keys.
  CurveSamples samples;
  const auto add = [&](double t, const Eigen::Vector3d& point) {
    samples.parameters.push_back(t == t1 ? 1.0 : (t - t0) / (t1 - t0));
    samples.points.push_back(point);
  };
  for (size_t i = 0; i < keys.size(); ++i) {
    if (i > 0 && keys[i] == keys[i - 1]) continue;
    if (i > 0) add(0.5 * (keys[i - 1] + keys[i]), 0.5 * (values[i - 1] + values[i]));
    add(keys[i], values[i]);
  }
  const int distinct_keys = static_cast<int>(samples.parameters.size() + 1) / 2;

  CurveFitOptions options;
  options.order = std::min(4, std::max(2, distinct_keys));
  options.optimise_weights = false;
  // The fit's tolerance leaves room for the written numbers' rounding; tightened when the bound of the
  // written curve still exceeds the deviation (the fit meets its tolerance at the samples only).
  double tolerance = 0.8 * deviation;
  for (int attempt = 0; attempt < 4; ++attempt, tolerance *= 0.5) {
    CurveFit fitted;
    try {
      fitted = fit_curve_within(samples, tolerance, options);
    } catch (const std::invalid_argument& e) {  // the data cannot be met with fewer control points
      throw GeometryError(kEntity, e.what());
    }
    // The ends on the first and last keys exactly, so an animation starts and stops where the original
    // does: a clamped curve passes through its end points, and moving one moves the curve by at most
    // that much (the bound below is taken afterwards).
    fitted.curve.points.front() = values.front();
    fitted.curve.points.back() = values.back();
    PositionPathFit fit;
    fit.curve = with_constant_ends(fitted.curve, t0, t1);
    fit.max_error = path_error_bound(written(fit.curve), keys, values);
    fit.fitted_samples = static_cast<int>(samples.parameters.size());
    if (fit.max_error <= deviation) return fit;
  }
  throw GeometryError(kEntity, "no fitted curve came within " + message_number(deviation) + " of the path");
}

}  // namespace cadnurbs
