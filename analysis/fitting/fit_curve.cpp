#include "analysis/fitting/fit_curve.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "analysis/fitting/curve_fit_energy.hpp"
#include "analysis/fitting/knot_gap_constraints.hpp"
#include "analysis/fitting/polak_ribiere.hpp"
#include "analysis/fitting/refinement_round.hpp"
#include "core/knot_insertion.hpp"
#include "core/knot_vector.hpp"
#include "core/number_format.hpp"

namespace cadnurbs {
namespace {

[[noreturn]] void refuse(const std::string& function, const std::string& reason) {
  throw std::invalid_argument(function + ": " + reason);
}

void check_samples(const CurveSamples& samples, const std::string& function) {
  if (samples.parameters.empty()) refuse(function, "no samples");
  if (samples.parameters.size() != samples.points.size()) {
    refuse(function, std::to_string(samples.parameters.size()) + " parameters for " +
                         std::to_string(samples.points.size()) + " points");
  }
  for (size_t j = 0; j < samples.parameters.size(); ++j) {
    const double t = samples.parameters[j];
    if (!std::isfinite(t) || t < 0 || t > 1)
      refuse(function, "parameter " + std::to_string(j) + " (" + number_text(t, 6) + ") is not in [0, 1]");
    if (j > 0 && t < samples.parameters[j - 1]) refuse(function, "parameter " + std::to_string(j) + " decreases");
    if (!samples.points[j].allFinite()) refuse(function, "point " + std::to_string(j) + " is not finite");
  }
}

int distinct_parameter_count(const std::vector<double>& parameters) {
  int distinct = 0;
  for (size_t j = 0; j < parameters.size(); ++j) distinct += j == 0 || parameters[j] != parameters[j - 1];
  return distinct;
}

void check_order(const CurveFitOptions& options, const std::string& function) {
  if (options.order < 2 || options.order > 16) refuse(function, "order " + std::to_string(options.order) + " is not in 2..16");
  if (!(options.minimum_knot_gap > 0)) refuse(function, "the minimum knot gap must be > 0");
  if (!(options.minimum_weight > 0)) refuse(function, "the minimum weight must be > 0");
}

// The conjugate-gradient unknowns: the interior knots (when optimised), then the weights (when optimised).
class FitVariables {
 public:
  FitVariables(int order, int count, const CurveFitOptions& options)
      : order_(order), count_(count), knots_(options.optimise_knots ? count - order : 0),
        weights_(options.optimise_weights ? count : 0), knot_scale_(count - order + 1),
        gap_(options.minimum_knot_gap * knot_scale_), minimum_weight_(options.minimum_weight),
        knot_block_{0, knots_, knot_scale_, gap_} {}

  Eigen::VectorXd pack(const std::vector<double>& knots, const std::vector<double>& weights) const {
    Eigen::VectorXd x(knots_ + weights_);
    for (int i = 0; i < knots_; ++i) x[i] = knots[order_ + i] * knot_scale_;
    for (int i = 0; i < weights_; ++i) x[knots_ + i] = weights[i];
    return x;
  }
  void unpack(const Eigen::VectorXd& x, std::vector<double>& knots, std::vector<double>& weights) const {
    for (int i = 0; i < knots_; ++i) knots[order_ + i] = x[i] / knot_scale_;
    for (int i = 0; i < weights_; ++i) weights[i] = x[knots_ + i];
  }
  Eigen::VectorXd pack_gradient(const CurveFitEvaluation& e) const {
    Eigen::VectorXd g(knots_ + weights_);
    for (int i = 0; i < knots_; ++i) g[i] = e.knot_gradient[order_ + i] / knot_scale_;
    for (int i = 0; i < weights_; ++i) g[knots_ + i] = e.weight_gradient[i];
    return g;
  }

  // Seed 003 §5.2: the knots' step bound (knot_gap_constraints), and likewise the weights' floor.
  double max_step(const Eigen::VectorXd& x, const Eigen::VectorXd& d) const {
    double bound = knot_block_.max_step(x, d);
    for (int i = 0; i < weights_; ++i) {
      const double w = x[knots_ + i], dw = d[knots_ + i];
      if (dw < 0) bound = std::min(bound, std::max(0.0, w - minimum_weight_) / -dw);
    }
    return bound;
  }

  // The nearest direction that keeps the active constraints: the knots' chains at the minimum gap
  // (knot_gap_constraints); a weight at its floor keeps no downward component.
  void adjust(const Eigen::VectorXd& x, Eigen::VectorXd& d) const {
    knot_block_.adjust(x, d);
    for (int w = 0; w < weights_; ++w) {
      if (x[knots_ + w] - minimum_weight_ <= 1e-12 && d[knots_ + w] < 0) d[knots_ + w] = 0;
    }
  }

  std::string fault(const Eigen::VectorXd& x, std::vector<double> knots, std::vector<double> weights) const {
    unpack(x, knots, weights);
    NurbsCurve curve;
    curve.order = order_;
    curve.knots = std::move(knots);
    curve.points.assign(count_, Eigen::Vector3d::Zero());
    curve.weights = std::move(weights);
    return fit_constraint_fault(curve, gap_ / knot_scale_);
  }

 private:
  int order_;
  int count_;
  int knots_;
  int weights_;
  double knot_scale_;  // knots are unknowns in units of the mean span, so that a unit step moves them as much as a weight
  double gap_;         // in those units
  double minimum_weight_;
  KnotGapBlock knot_block_;
};

double distance_at(const NurbsCurve& curve, const CurveSamples& samples, size_t j) {
  return (curve_point(curve, samples.parameters[j]) - samples.points[j]).norm();
}

// The fit from given starting knots and weights (both feasible): CG over the free ones (unless
// `minimise` is false: the start's control points only), then the curve and its errors at the samples.
CurveFit fit_from(const CurveSamples& samples, std::vector<double> knots, std::vector<double> weights,
                  const CurveFitOptions& options, bool minimise = true) {
  const int order = options.order;
  const int count = static_cast<int>(weights.size());
  CurveFitEnergyTerms terms;
  terms.fairness = options.fairness;
  terms.knot_spread = options.optimise_knots ? options.knot_spread : 0.0;
  terms.weight_pull = options.optimise_weights ? options.weight_pull : 0.0;
  terms.minimum_gap = options.minimum_knot_gap;
  const CurveFitEvaluation start =
      evaluate_curve_fit_energy(samples.parameters, samples.points, order, knots, weights, terms, false);
  terms.scale = start.data_energy + start.fairness_energy;

  const FitVariables variables(order, count, options);
  CurveFit fit;
  Eigen::VectorXd x = variables.pack(knots, weights);
  if (minimise && x.size() > 0) {
    std::vector<double> trial_knots = knots, trial_weights = weights;
    const EnergyWithGradient energy = [&](const Eigen::VectorXd& at, Eigen::VectorXd* gradient) {
      variables.unpack(at, trial_knots, trial_weights);
      const CurveFitEvaluation e = evaluate_curve_fit_energy(samples.parameters, samples.points, order, trial_knots,
                                                             trial_weights, terms, gradient != nullptr);
      if (gradient && std::isfinite(e.energy)) *gradient = variables.pack_gradient(e);
      return e.energy;
    };
    FeasibilityHooks hooks;
    hooks.max_step = [&](const Eigen::VectorXd& at, const Eigen::VectorXd& d) { return variables.max_step(at, d); };
    hooks.adjust_direction = [&](const Eigen::VectorXd& at, Eigen::VectorXd& d) { variables.adjust(at, d); };
    hooks.on_iterate = [&](const Eigen::VectorXd& at) {
      // Debug builds check the hard constraints on every accepted iterate (the requirement).
      assert(variables.fault(at, knots, weights).empty());
      (void)at;
    };
    PolakRibiereOptions cg;
    cg.max_iterations = options.max_iterations;
    const PolakRibiereResult result = minimise_polak_ribiere(energy, x, hooks, cg);
    variables.unpack(result.x, knots, weights);
    fit.iterations = result.iterations;
  }
  const CurveFitEvaluation final_state =
      evaluate_curve_fit_energy(samples.parameters, samples.points, order, knots, weights, terms, false);
  if (!std::isfinite(final_state.energy)) refuse("fit_curve", "the samples do not determine the control points");
  fit.curve.dimension = 3;
  fit.curve.order = order;
  fit.curve.knots = std::move(knots);
  fit.curve.points = final_state.control_points;
  if (options.optimise_weights) fit.curve.weights = std::move(weights);
  double sum = 0;
  for (size_t j = 0; j < samples.parameters.size(); ++j) {
    const double distance = distance_at(fit.curve, samples, j);
    fit.max_error = std::max(fit.max_error, distance);
    sum += distance * distance;
  }
  fit.rms_error = std::sqrt(sum / samples.parameters.size());
  return fit;
}

std::vector<double> initial_knots(const CurveSamples& samples, int count, const CurveFitOptions& options,
                                  const std::string& function) {
  const int spans = count - options.order + 1;
  if (spans * options.minimum_knot_gap >= 1) {
    refuse(function, std::to_string(spans) + " spans do not fit in [0, 1] at the minimum knot gap " +
                         number_text(options.minimum_knot_gap, 6));
  }
  std::vector<double> knots = options.initial_knots == InitialKnots::uniform
                                  ? clamped_uniform_knots(options.order, count)
                                  : averaged_knots(samples.parameters, options.order, count);
  keep_knot_gaps(knots, options.order, count, options.minimum_knot_gap);
  return knots;
}

}  // namespace

std::string fit_constraint_fault(const NurbsCurve& curve, double minimum_gap) {
  const int order = curve.order;
  const int count = curve.count();
  if (static_cast<int>(curve.knots.size()) != count + order) return "the knot vector has the wrong length";
  for (int i = 0; i < order; ++i) {
    if (curve.knots[i] != 0.0) return "knot " + std::to_string(i) + " is not 0 (the start is not clamped at 0)";
    if (curve.knots[count + i] != 1.0) return "knot " + std::to_string(count + i) + " is not 1 (the end is not clamped at 1)";
  }
  for (int i = order - 1; i < count; ++i) {
    const double gap = curve.knots[i + 1] - curve.knots[i];
    if (!(gap >= minimum_gap * (1 - 1e-9))) {
      return "knots " + std::to_string(i) + " and " + std::to_string(i + 1) + " are " + number_text(gap, 6) +
             " apart, less than the minimum gap " + number_text(minimum_gap, 6);
    }
  }
  for (size_t i = 0; i < curve.weights.size(); ++i) {
    if (!(curve.weights[i] > 0) || !std::isfinite(curve.weights[i])) return "weight " + std::to_string(i) + " is not > 0";
  }
  return {};
}

CurveFit fit_curve(const CurveSamples& samples, int control_points, const CurveFitOptions& options) {
  const std::string function = "fit_curve";
  check_samples(samples, function);
  check_order(options, function);
  const int distinct = distinct_parameter_count(samples.parameters);
  if (control_points < options.order) {
    refuse(function, std::to_string(control_points) + " control points are fewer than the order " +
                         std::to_string(options.order));
  }
  if (control_points > distinct) {
    refuse(function, std::to_string(control_points) + " control points need at least as many distinct sample parameters (" +
                         std::to_string(distinct) + ")");
  }
  return fit_from(samples, initial_knots(samples, control_points, options, function),
                  std::vector<double>(control_points, 1.0), options);
}

CurveFit fit_curve_within(const CurveSamples& samples, double tolerance, const CurveFitOptions& options) {
  const std::string function = "fit_curve_within";
  check_samples(samples, function);
  check_order(options, function);
  if (!(tolerance > 0)) refuse(function, "the tolerance must be > 0");
  const int distinct = distinct_parameter_count(samples.parameters);
  if (distinct < options.order) {
    refuse(function, std::to_string(distinct) + " distinct sample parameters cannot fix a curve of order " +
                         std::to_string(options.order));
  }
  const int start_count = std::min(options.order + 1, distinct);
  std::vector<double> knots = initial_knots(samples, start_count, options, function);
  std::vector<double> weights(start_count, 1.0);
  int iterations = 0;
  for (int round = 0;; ++round) {
    CurveFit fit = refinement_round(
        [&](bool minimise) { return fit_from(samples, knots, weights, options, minimise); }, tolerance, round, iterations);
    if (fit.max_error <= tolerance) return fit;

    // Knots at the middle of every span holding a sample beyond the tolerance (seed 002: refine only
    // where the fit fails, so the rest of the curve keeps its few control points).
    const NurbsCurve& curve = fit.curve;
    std::vector<double> inserted;
    for (size_t j = 0; j < samples.parameters.size(); ++j) {
      if (distance_at(curve, samples, j) <= tolerance) continue;
      const int span = find_knot_span(curve.knots, curve.order, curve.count(), samples.parameters[j]);
      const double start = curve.knots[span], end = curve.knots[span + 1];
      const double middle = 0.5 * (start + end);
      if (!inserted.empty() && inserted.back() == middle) continue;
      if (0.5 * (end - start) < options.minimum_knot_gap) {
        refuse(function, "the data cannot be met within " + number_text(tolerance, 6) + ": the span [" +
                             number_text(start, 6) + ", " + number_text(end, 6) + "] still misses a sample by " +
                             number_text(distance_at(curve, samples, j), 6) +
                             " and is too short to split at the minimum knot gap " +
                             number_text(options.minimum_knot_gap, 6));
      }
      inserted.push_back(middle);
    }
    const int needed = curve.count() + static_cast<int>(inserted.size());
    if (needed > distinct && curve.count() < distinct) {
      // The last resort before refusing: as many control points as distinct parameters, which meets
      // the samples whenever the averaged knots let the spline interpolate them.
      CurveFit last = fit_curve(samples, distinct, options);
      last.iterations += iterations;
      last.refinements = round + 1;
      if (last.max_error <= tolerance) return last;
    }
    if (needed > distinct) {
      refuse(function, "the data cannot be met within " + number_text(tolerance, 6) + ": the refinement would need " +
                           std::to_string(needed) + " control points, more than the " + std::to_string(distinct) +
                           " distinct sample parameters (max error still " + number_text(fit.max_error, 6) + ")");
    }
    const NurbsCurve refined = refine_knots(curve, inserted);
    knots = refined.knots;
    weights = refined.is_rational() ? refined.weights : std::vector<double>(refined.count(), 1.0);
  }
}

}  // namespace cadnurbs
