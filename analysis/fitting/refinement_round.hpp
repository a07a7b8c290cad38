#pragma once
// One round of the fitters' hierarchical refinement (seed 002), shared by fit_curve_within and
// fit_surface_within: the fit at the round's knots as they come (control points solved, nothing
// moved), and only when that start misses the tolerance the minimised fit, since the minimisation
// lowers the mean squared error, not always the largest one. The CG iterations are summed over the
// rounds into `iterations`, and the fit records the sum and its round.
namespace cadnurbs {

// fit_from(bool minimise) -> Fit with max_error, iterations and refinements members.
template <class FitFrom>
auto refinement_round(const FitFrom& fit_from, double tolerance, int round, int& iterations) {
  auto fit = fit_from(false);
  if (fit.max_error > tolerance) fit = fit_from(true);
  iterations += fit.iterations;
  fit.iterations = iterations;
  fit.refinements = round;
  return fit;
}

}  // namespace cadnurbs
