#pragma once
// The energy fit_curve minimises, as a function of the knots and weights alone (the reduced energy).
//
//   E = (1/m) Σ_j |C(t_j) - P_j|²                 fit to the m samples at their fixed parameters
//     + fairness · ∫_0^1 |C''(t)|² dt              bending (per knot span: Gauss-Legendre, Simpson where knots crowd)
//     + knot_spread · scale · mean_s (gap / h_s)²  keeps spans h_s away from the minimum gap
//     + weight_pull · scale · mean_i (w_i - 1)²    keeps weights near 1 (and fixes the rational scale freedom)
//
// For fixed knots and weights E is quadratic in the control points, so they are solved exactly (banded
// normal equations, sparse LDLᵀ); the gradient with respect to knots and weights then needs no term
// through the control points (they are optimal). It is taken over the rational Bézier
// re-parametrisation of seed 003 §4: the energy's gradient with respect to each span's homogeneous
// Bézier points and span ends, chained through the Bézier points' exact derivatives with respect to
// the knots (bezier_span_basis with a dual number) and the weights.
#include <Eigen/Core>
#include <vector>

namespace cadnurbs {

struct CurveFitEnergyTerms {
  double fairness = 0;
  double knot_spread = 0;
  double weight_pull = 0;
  double minimum_gap = 0;  // spans at most 4 gaps long count as crowded: Simpson's rule there
  double scale = 1;        // the energy unit of the two small terms (the caller's start fit energy)
};

struct CurveFitEvaluation {
  double energy = 0;
  double data_energy = 0;      // the first term alone
  double fairness_energy = 0;  // the second term, fairness weight included
  std::vector<Eigen::Vector3d> control_points;  // the optimal control points for these knots and weights
  std::vector<double> knot_gradient;            // dE/du_i for every knot (ends included; callers hold them fixed)
  std::vector<double> weight_gradient;          // dE/dw_i
};

// parameters (non-decreasing, inside the knots' domain) and points: the samples. knots: a clamped
// vector of weights.size() + order values whose spans in the domain are all non-empty; weights > 0.
// Gradients only when `with_gradient`. Returns energy = +infinity when the normal equations are
// singular (too few samples to fix the control points). Checks nothing else (the fitter's job).
CurveFitEvaluation evaluate_curve_fit_energy(const std::vector<double>& parameters,
                                             const std::vector<Eigen::Vector3d>& points, int order,
                                             const std::vector<double>& knots, const std::vector<double>& weights,
                                             const CurveFitEnergyTerms& terms, bool with_gradient);

}  // namespace cadnurbs
