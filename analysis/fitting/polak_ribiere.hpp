#pragma once
// A small minimiser: Polak-Ribière nonlinear conjugate gradient (the PR+ form, beta >= 0) over an
// Eigen::VectorXd, for energies with hard constraints (seed 003 §5.2). The caller keeps its constraints
// through two hooks, as 003 describes for knots and weights: it adjusts each search direction to the
// constraints active at the current point, and it bounds how far the line search may go along it, so
// that every iterate stays feasible. Generic: nothing here knows about curves or surfaces.
#include <Eigen/Core>
#include <functional>

namespace cadnurbs {

// The energy at x; when `gradient` is not null, also its gradient there (resized by the callee).
// May return +infinity for a point it refuses: the line search then steps back.
using EnergyWithGradient = std::function<double(const Eigen::VectorXd& x, Eigen::VectorXd* gradient)>;

struct FeasibilityHooks {
  // Changes `direction` so that moving along it from the feasible x keeps the constraints that are
  // active at x (e.g. moves colliding knots together, zeroes the push of a weight at its floor).
  // Empty: directions are used as they are.
  std::function<void(const Eigen::VectorXd& x, Eigen::VectorXd& direction)> adjust_direction;
  // The largest a >= 0 with x + a * direction feasible (infinity when nothing bounds it). Empty: unbounded.
  std::function<double(const Eigen::VectorXd& x, const Eigen::VectorXd& direction)> max_step;
  // Called with the start and every accepted iterate: the place for the caller's debug assertions.
  std::function<void(const Eigen::VectorXd& x)> on_iterate;
};

struct PolakRibiereOptions {
  int max_iterations = 200;
  // Stop when an iteration lowers the energy by less than this fraction of it.
  double relative_tolerance = 1e-10;
  // Stop when the adjusted steepest-descent direction is no longer than this.
  double gradient_tolerance = 0;
  // Restart with steepest descent every this many iterations; 0: every x.size() iterations.
  int restart_interval = 0;
};

struct PolakRibiereResult {
  Eigen::VectorXd x;       // the last accepted iterate (feasible)
  double energy = 0;       // the energy at x
  int iterations = 0;      // accepted line searches
  bool converged = false;  // false when max_iterations ended the run
};

// Minimises `energy` from the feasible x0. Each iteration searches along the adjusted direction with a
// bracketing line search (sufficient decrease, strong curvature condition) that never goes beyond
// hooks.max_step; a direction that does not descend is replaced by the adjusted steepest descent, and
// the run stops when even that cannot lower the energy. Refuses (std::invalid_argument) an x0 whose
// energy is not finite.
PolakRibiereResult minimise_polak_ribiere(const EnergyWithGradient& energy, const Eigen::VectorXd& x0,
                                          const FeasibilityHooks& hooks = {},
                                          const PolakRibiereOptions& options = {});

}  // namespace cadnurbs
