#include "analysis/fitting/polak_ribiere.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

namespace cadnurbs {
namespace {

// Line search constants (Nocedal & Wright §3.1): a small c1, and for conjugate gradient a tight c2 so
// that successive directions stay close to conjugate.
constexpr double kSufficientDecrease = 1e-4;
constexpr double kCurvature = 0.1;
constexpr int kMaxExpansions = 40;
constexpr int kMaxZoomSteps = 40;

struct Trial {
  double a = 0;
  double f = 0;
  double slope = 0;  // d/da of the energy along the direction
  Eigen::VectorXd x;
  Eigen::VectorXd gradient;
};

class LineSearch {
 public:
  LineSearch(const EnergyWithGradient& energy, const Eigen::VectorXd& x, double f0, double slope0,
             const Eigen::VectorXd& direction)
      : energy_(energy), x_(x), f0_(f0), slope0_(slope0), direction_(direction) {}

  // A step in (0, a_max] that lowers the energy enough, or nothing when none was found.
  std::optional<Trial> run(double a_first, double a_max) {
    Trial lo;
    lo.f = f0_;
    lo.slope = slope0_;
    double a = std::min(a_first, a_max);
    for (int i = 0; i < kMaxExpansions; ++i) {
      Trial t = evaluate(a);
      if (!decreases_enough(t) || t.f >= lo.f) return zoom(lo, t);
      if (std::abs(t.slope) <= kCurvature * std::abs(slope0_)) return t;
      if (t.slope >= 0) return zoom(t, lo);
      if (a >= a_max) return t;  // still descending at the bound: the constraint stops us here
      lo = t;
      a = std::min(a_max, 4 * a);
    }
    return accepted(lo);
  }

 private:
  Trial evaluate(double a) const {
    Trial t;
    t.a = a;
    t.x = x_ + a * direction_;
    t.f = energy_(t.x, &t.gradient);
    t.slope = std::isfinite(t.f) ? t.gradient.dot(direction_) : std::numeric_limits<double>::quiet_NaN();
    return t;
  }
  bool decreases_enough(const Trial& t) const {
    return std::isfinite(t.f) && t.f <= f0_ + kSufficientDecrease * t.a * slope0_;
  }
  static std::optional<Trial> accepted(const Trial& t) {
    if (t.a > 0) return t;
    return std::nullopt;
  }

  // lo: the best step so far (meets sufficient decrease, or is the start); hi: the other end of an
  // interval that holds a step meeting both conditions.
  std::optional<Trial> zoom(Trial lo, Trial hi) {
    for (int i = 0; i < kMaxZoomSteps; ++i) {
      const double width = hi.a - lo.a;
      if (std::abs(width) <= 1e-15 * std::max(1.0, std::abs(lo.a))) break;
      // Minimum of the quadratic through lo's value and slope and hi's value, kept well inside.
      double a = lo.a + 0.5 * width;
      if (std::isfinite(hi.f)) {
        const double curvature = (hi.f - lo.f - lo.slope * width) / (width * width);
        if (curvature > 0) a = lo.a - lo.slope / (2 * curvature);
      }
      const double inner_lo = lo.a + 0.1 * width;
      const double inner_hi = lo.a + 0.9 * width;
      a = std::clamp(a, std::min(inner_lo, inner_hi), std::max(inner_lo, inner_hi));
      Trial t = evaluate(a);
      if (!decreases_enough(t) || t.f >= lo.f) {
        hi = std::move(t);
        continue;
      }
      if (std::abs(t.slope) <= kCurvature * std::abs(slope0_)) return t;
      if (t.slope * (hi.a - lo.a) >= 0) hi = lo;
      lo = std::move(t);
    }
    return accepted(lo);
  }

  const EnergyWithGradient& energy_;
  const Eigen::VectorXd& x_;
  double f0_;
  double slope0_;
  const Eigen::VectorXd& direction_;
};

}  // namespace

PolakRibiereResult minimise_polak_ribiere(const EnergyWithGradient& energy, const Eigen::VectorXd& x0,
                                          const FeasibilityHooks& hooks, const PolakRibiereOptions& options) {
  PolakRibiereResult result;
  result.x = x0;
  Eigen::VectorXd gradient;
  result.energy = energy(result.x, &gradient);
  if (!std::isfinite(result.energy)) throw std::invalid_argument("Polak-Ribiere: the start's energy is not finite");
  if (hooks.on_iterate) hooks.on_iterate(result.x);
  if (x0.size() == 0) {
    result.converged = true;
    return result;
  }

  const int restart_interval = options.restart_interval > 0 ? options.restart_interval : static_cast<int>(x0.size());
  auto steepest_descent = [&] {
    Eigen::VectorXd d = -gradient;
    if (hooks.adjust_direction) hooks.adjust_direction(result.x, d);
    return d;
  };

  Eigen::VectorXd direction = steepest_descent();
  bool is_steepest = true;
  int since_restart = 0;
  double previous_step = 0;
  double previous_slope = 0;
  while (result.iterations < options.max_iterations) {
    const double slope = gradient.dot(direction);
    if (!(slope < 0) || (is_steepest && direction.norm() <= options.gradient_tolerance)) {
      if (is_steepest) {
        result.converged = true;  // no feasible descent left: a constrained stationary point
        break;
      }
      direction = steepest_descent();
      is_steepest = true;
      since_restart = 0;
      continue;
    }
    const double a_max = hooks.max_step ? hooks.max_step(result.x, direction) : std::numeric_limits<double>::infinity();
    // First trial: the step whose first-order change equals the last iteration's (Nocedal & Wright 3.60).
    double a_first = previous_step > 0 ? previous_step * previous_slope / slope
                                       : 1.0 / std::max(direction.lpNorm<Eigen::Infinity>(), 1e-300);
    std::optional<Trial> step;
    if (a_max > 0) step = LineSearch(energy, result.x, result.energy, slope, direction).run(a_first, a_max);
    if (!step) {
      if (is_steepest) {
        result.converged = true;
        break;
      }
      direction = steepest_descent();
      is_steepest = true;
      since_restart = 0;
      continue;
    }
    ++result.iterations;
    const double previous_energy = result.energy;
    const Eigen::VectorXd previous_gradient = gradient;
    result.x = std::move(step->x);
    result.energy = step->f;
    gradient = std::move(step->gradient);
    if (hooks.on_iterate) hooks.on_iterate(result.x);
    previous_step = step->a;
    previous_slope = slope;

    const bool small_decrease =
        previous_energy - result.energy <= options.relative_tolerance * std::max(std::abs(previous_energy), 1e-300);
    if (small_decrease && is_steepest) {
      result.converged = true;
      break;
    }
    double beta = 0;
    ++since_restart;
    if (!small_decrease && since_restart < restart_interval) {
      beta = std::max(0.0, gradient.dot(gradient - previous_gradient) / previous_gradient.squaredNorm());
    }
    if (beta == 0) since_restart = 0;
    direction = -gradient + beta * direction;
    if (hooks.adjust_direction) hooks.adjust_direction(result.x, direction);
    is_steepest = beta == 0;
  }
  return result;
}

}  // namespace cadnurbs
