#include "analysis/fitting/fit_surface.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <set>
#include <stdexcept>

#include "analysis/fitting/curve_fit_energy.hpp"
#include "analysis/fitting/knot_gap_constraints.hpp"
#include "analysis/fitting/polak_ribiere.hpp"
#include "analysis/fitting/refinement_round.hpp"
#include "core/knot_vector.hpp"
#include "core/number_format.hpp"

namespace cadnurbs {
namespace {

[[noreturn]] void refuse(const std::string& function, const std::string& reason) {
  throw std::invalid_argument(function + ": " + reason);
}

void check_parameters(const std::vector<double>& parameters, const std::string& direction, const std::string& function) {
  for (size_t i = 0; i < parameters.size(); ++i) {
    const double t = parameters[i];
    if (!std::isfinite(t) || t < 0 || t > 1) {
      refuse(function, direction + " parameter " + std::to_string(i) + " (" + message_number(t) + ") is not in [0, 1]");
    }
    if (i > 0 && !(t > parameters[i - 1])) refuse(function, direction + " parameter " + std::to_string(i) + " does not increase");
  }
}

void check_grid(const GridSamples& grid, const std::string& function) {
  if (grid.u.empty() || grid.v.empty()) refuse(function, "no samples");
  if (grid.points.size() != grid.u.size() * grid.v.size()) {
    refuse(function, std::to_string(grid.u.size()) + " x " + std::to_string(grid.v.size()) + " parameters for " +
                         std::to_string(grid.points.size()) + " points");
  }
  check_parameters(grid.u, "u", function);
  check_parameters(grid.v, "v", function);
  for (size_t k = 0; k < grid.points.size(); ++k) {
    if (!grid.points[k].allFinite()) refuse(function, "point " + std::to_string(k) + " is not finite");
  }
}

void check_options(const SurfaceFitOptions& options, const std::string& function) {
  for (const auto& [order, direction] : {std::pair{options.u_order, "u"}, std::pair{options.v_order, "v"}}) {
    if (order < 2 || order > 16) refuse(function, std::string(direction) + " order " + std::to_string(order) + " is not in 2..16");
  }
  if (!(options.minimum_knot_gap > 0)) refuse(function, "the minimum knot gap must be > 0");
}

void check_count(int count, int order, size_t parameters, const std::string& direction, const std::string& function) {
  if (count < order) {
    refuse(function, std::to_string(count) + " " + direction + " control points are fewer than the " + direction +
                         " order " + std::to_string(order));
  }
  if (count > static_cast<int>(parameters)) {
    refuse(function, std::to_string(count) + " " + direction + " control points need at least as many " + direction +
                         " parameters (" + std::to_string(parameters) + ")");
  }
}

std::vector<double> initial_knots(const std::vector<double>& parameters, int order, int count,
                                  const SurfaceFitOptions& options, const std::string& direction,
                                  const std::string& function) {
  const int spans = count - order + 1;
  if (spans * options.minimum_knot_gap >= 1) {
    refuse(function, std::to_string(spans) + " " + direction + " spans do not fit in [0, 1] at the minimum knot gap " +
                         message_number(options.minimum_knot_gap));
  }
  std::vector<double> knots = options.initial_knots == InitialKnots::uniform ? clamped_uniform_knots(order, count)
                                                                             : averaged_knots(parameters, order, count);
  keep_knot_gaps(knots, order, count, options.minimum_knot_gap);
  return knots;
}

// The interior knots of one direction among the CG unknowns, in units of that direction's mean span.
KnotGapBlock knot_block(int offset, int order, int count, const SurfaceFitOptions& options) {
  const double scale = count - order + 1;
  return {offset, options.optimise_knots ? count - order : 0, scale, options.minimum_knot_gap * scale};
}

// A curve with these knots and no points: what fit_constraint_fault reads.
[[maybe_unused]] std::string knots_fault(int order, const std::vector<double>& knots, double minimum_gap) {
  NurbsCurve curve;
  curve.order = order;
  curve.knots = knots;
  curve.points.assign(knots.size() - order, Eigen::Vector3d::Zero());
  return fit_constraint_fault(curve, minimum_gap);
}

std::vector<double> grid_errors(const NurbsSurface& surface, const GridSamples& grid) {
  const size_t m = grid.u.size();
  std::vector<double> errors(grid.points.size());
  for (size_t j = 0; j < grid.v.size(); ++j) {
    for (size_t i = 0; i < m; ++i) errors[i + j * m] = (surface_point(surface, grid.u[i], grid.v[j]) - grid.points[i + j * m]).norm();
  }
  return errors;
}

// The fit from given feasible knots: CG over the interior knots of both directions (unless `minimise`
// is false), then the surface and its errors on the grid.
SurfaceFit fit_from(const GridSamples& grid, std::vector<double> u_knots, std::vector<double> v_knots,
                    const SurfaceFitOptions& options, bool minimise = true) {
  const int u_order = options.u_order, v_order = options.v_order;
  const int u_count = static_cast<int>(u_knots.size()) - u_order, v_count = static_cast<int>(v_knots.size()) - v_order;
  SurfaceFitEnergyTerms terms;
  terms.fairness = options.fairness;
  terms.knot_spread = options.optimise_knots ? options.knot_spread : 0.0;
  terms.minimum_gap = options.minimum_knot_gap;
  const SurfaceFitEvaluation start = evaluate_surface_fit_energy(grid, u_order, v_order, u_knots, v_knots, terms, false);
  if (!std::isfinite(start.energy)) refuse("fit_surface", "the samples do not determine the control points");
  terms.scale = start.data_energy + start.fairness_energy;

  const KnotGapBlock u_block = knot_block(0, u_order, u_count, options);
  const KnotGapBlock v_block = knot_block(u_block.size, v_order, v_count, options);
  auto pack = [&](const std::vector<double>& u, const std::vector<double>& v) {
    Eigen::VectorXd x(u_block.size + v_block.size);
    for (int i = 0; i < u_block.size; ++i) x[i] = u[u_order + i] * u_block.scale;
    for (int i = 0; i < v_block.size; ++i) x[v_block.offset + i] = v[v_order + i] * v_block.scale;
    return x;
  };
  auto unpack = [&](const Eigen::VectorXd& x, std::vector<double>& u, std::vector<double>& v) {
    for (int i = 0; i < u_block.size; ++i) u[u_order + i] = x[i] / u_block.scale;
    for (int i = 0; i < v_block.size; ++i) v[v_order + i] = x[v_block.offset + i] / v_block.scale;
  };

  SurfaceFit fit;
  const Eigen::VectorXd x = pack(u_knots, v_knots);
  if (minimise && x.size() > 0) {
    std::vector<double> trial_u = u_knots, trial_v = v_knots;
    const EnergyWithGradient energy = [&](const Eigen::VectorXd& at, Eigen::VectorXd* gradient) {
      unpack(at, trial_u, trial_v);
      const SurfaceFitEvaluation e =
          evaluate_surface_fit_energy(grid, u_order, v_order, trial_u, trial_v, terms, gradient != nullptr);
      if (gradient && std::isfinite(e.energy)) {
        gradient->resize(at.size());
        for (int i = 0; i < u_block.size; ++i) (*gradient)[i] = e.u_knot_gradient[u_order + i] / u_block.scale;
        for (int i = 0; i < v_block.size; ++i) {
          (*gradient)[v_block.offset + i] = e.v_knot_gradient[v_order + i] / v_block.scale;
        }
      }
      return e.energy;
    };
    FeasibilityHooks hooks;
    hooks.max_step = [&](const Eigen::VectorXd& at, const Eigen::VectorXd& d) {
      return std::min(u_block.max_step(at, d), v_block.max_step(at, d));
    };
    hooks.adjust_direction = [&](const Eigen::VectorXd& at, Eigen::VectorXd& d) {
      u_block.adjust(at, d);
      v_block.adjust(at, d);
    };
    hooks.on_iterate = [&](const Eigen::VectorXd& at) {
      // Debug builds check the hard constraints on every accepted iterate, as fit_curve does.
      std::vector<double> u = u_knots, v = v_knots;
      unpack(at, u, v);
      assert(knots_fault(u_order, u, options.minimum_knot_gap).empty());
      assert(knots_fault(v_order, v, options.minimum_knot_gap).empty());
      (void)u;
      (void)v;
    };
    PolakRibiereOptions cg;
    cg.max_iterations = options.max_iterations;
    const PolakRibiereResult result = minimise_polak_ribiere(energy, x, hooks, cg);
    unpack(result.x, u_knots, v_knots);
    fit.iterations = result.iterations;
  }
  const SurfaceFitEvaluation final_state =
      evaluate_surface_fit_energy(grid, u_order, v_order, u_knots, v_knots, terms, false);
  if (!std::isfinite(final_state.energy)) refuse("fit_surface", "the samples do not determine the control points");
  NurbsSurface& surface = fit.surface;
  surface.u_order = u_order;
  surface.v_order = v_order;
  surface.u_count = u_count;
  surface.v_count = v_count;
  surface.u_knots = std::move(u_knots);
  surface.v_knots = std::move(v_knots);
  surface.points = final_state.control_points;
  double sum = 0;
  for (double error : grid_errors(surface, grid)) {
    fit.max_error = std::max(fit.max_error, error);
    sum += error * error;
  }
  fit.rms_error = std::sqrt(sum / grid.points.size());
  return fit;
}

// Each grid point's error when its row alone is fitted in u with the surface's u knots (the v
// direction resolved exactly): large where the u knots are at fault. Row by row with the curve
// fitter's solve; `transpose` does the same for columns in v.
std::vector<double> one_direction_errors(const GridSamples& grid, int order, const std::vector<double>& knots,
                                         const SurfaceFitOptions& options, bool transpose) {
  const size_t m = grid.u.size();
  const std::vector<double>& along = transpose ? grid.v : grid.u;
  const size_t lines = transpose ? m : grid.v.size();
  const int count = static_cast<int>(knots.size()) - order;
  CurveFitEnergyTerms terms;
  terms.fairness = options.fairness;
  terms.minimum_gap = options.minimum_knot_gap;
  NurbsCurve curve;
  curve.order = order;
  curve.knots = knots;
  std::vector<double> errors(grid.points.size());
  std::vector<Eigen::Vector3d> points(along.size());
  for (size_t line = 0; line < lines; ++line) {
    auto index = [&](size_t k) { return transpose ? line + k * m : k + line * m; };
    for (size_t k = 0; k < along.size(); ++k) points[k] = grid.points[index(k)];
    curve.points =
        evaluate_curve_fit_energy(along, points, order, knots, std::vector<double>(count, 1.0), terms, false).control_points;
    if (curve.points.empty()) continue;  // a singular line: the surface's own error decides below
    for (size_t k = 0; k < along.size(); ++k) errors[index(k)] = (curve_point(curve, along[k]) - points[k]).norm();
  }
  return errors;
}

// The middles of the marked spans, merged into the knot vector; refuses a span too short to split.
void split_spans(std::vector<double>& knots, const std::set<int>& spans, const SurfaceFitOptions& options,
                 double tolerance, double max_error, const std::string& direction, const std::string& function) {
  std::vector<double> middles;
  for (int span : spans) {
    const double start = knots[span], end = knots[span + 1];
    if (0.5 * (end - start) < options.minimum_knot_gap) {
      refuse(function, "the data cannot be met within " + message_number(tolerance) + ": the " + direction + " span [" +
                           message_number(start) + ", " + message_number(end) +
                           "] is at fault and too short to split at the minimum knot gap " +
                           message_number(options.minimum_knot_gap) + " (max error still " + message_number(max_error) + ")");
    }
    middles.push_back(0.5 * (start + end));
  }
  knots.insert(knots.end(), middles.begin(), middles.end());
  std::sort(knots.begin(), knots.end());
}

}  // namespace

SurfaceFit fit_surface(const GridSamples& grid, int u_control_points, int v_control_points,
                       const SurfaceFitOptions& options) {
  const std::string function = "fit_surface";
  check_grid(grid, function);
  check_options(options, function);
  check_count(u_control_points, options.u_order, grid.u.size(), "u", function);
  check_count(v_control_points, options.v_order, grid.v.size(), "v", function);
  return fit_from(grid, initial_knots(grid.u, options.u_order, u_control_points, options, "u", function),
                  initial_knots(grid.v, options.v_order, v_control_points, options, "v", function), options);
}

SurfaceFit fit_surface_within(const GridSamples& grid, double tolerance, const SurfaceFitOptions& options) {
  const std::string function = "fit_surface_within";
  check_grid(grid, function);
  check_options(options, function);
  if (!(tolerance > 0)) refuse(function, "the tolerance must be > 0");
  const int m = static_cast<int>(grid.u.size()), n = static_cast<int>(grid.v.size());
  for (const auto& [parameters, order, direction] :
       {std::tuple{m, options.u_order, "u"}, std::tuple{n, options.v_order, "v"}}) {
    if (parameters < order) {
      refuse(function, std::to_string(parameters) + " " + direction + " parameters cannot fix a surface of " + direction +
                           " order " + std::to_string(order));
    }
  }
  std::vector<double> u_knots =
      initial_knots(grid.u, options.u_order, std::min(options.u_order + 1, m), options, "u", function);
  std::vector<double> v_knots =
      initial_knots(grid.v, options.v_order, std::min(options.v_order + 1, n), options, "v", function);
  int iterations = 0;
  for (int round = 0;; ++round) {
    SurfaceFit fit = refinement_round(
        [&](bool minimise) { return fit_from(grid, u_knots, v_knots, options, minimise); }, tolerance, round, iterations);
    if (fit.max_error <= tolerance) return fit;

    // Seed 002: refine only the spans at fault, so that the rest of the surface keeps its few control
    // points; the one-direction fits say which direction a missed grid point blames.
    const NurbsSurface& surface = fit.surface;
    const std::vector<double> errors = grid_errors(surface, grid);
    const std::vector<double> u_errors = one_direction_errors(grid, options.u_order, surface.u_knots, options, false);
    const std::vector<double> v_errors = one_direction_errors(grid, options.v_order, surface.v_knots, options, true);
    std::set<int> u_spans, v_spans;
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < m; ++i) {
        const int k = i + j * m;
        if (errors[k] <= tolerance) continue;
        bool in_u = u_errors[k] > 0.5 * tolerance, in_v = v_errors[k] > 0.5 * tolerance;
        if (!in_u && !in_v) (u_errors[k] >= v_errors[k] ? in_u : in_v) = true;
        if (in_u) u_spans.insert(find_knot_span(surface.u_knots, surface.u_order, surface.u_count, grid.u[i]));
        if (in_v) v_spans.insert(find_knot_span(surface.v_knots, surface.v_order, surface.v_count, grid.v[j]));
      }
    }
    for (const auto& [spans, count, parameters, direction] :
         {std::tuple{&u_spans, surface.u_count, m, "u"}, std::tuple{&v_spans, surface.v_count, n, "v"}}) {
      const int needed = count + static_cast<int>(spans->size());
      if (needed > parameters) {
        refuse(function, "the data cannot be met within " + message_number(tolerance) + ": the refinement would need " +
                             std::to_string(needed) + " " + direction + " control points, more than the " +
                             std::to_string(parameters) + " " + direction + " parameters (max error still " +
                             message_number(fit.max_error) + ")");
      }
    }
    u_knots = surface.u_knots;
    v_knots = surface.v_knots;
    split_spans(u_knots, u_spans, options, tolerance, fit.max_error, "u", function);
    split_spans(v_knots, v_spans, options, tolerance, fit.max_error, "v", function);
  }
}

}  // namespace cadnurbs
