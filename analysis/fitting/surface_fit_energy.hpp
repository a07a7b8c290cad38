#pragma once
// The energy fit_surface minimises, as a function of the u and v knots alone (the reduced energy), for
// gridded data: an m x n grid of points P_ij at parameters (u_i, v_j), fitted by a polynomial
// tensor-product B-spline S(u, v) = Σ_ab N_a(u) M_b(v) Q_ab.
//
//   E = (1/mn) Σ_ij |S(u_i, v_j) - P_ij|²                                  fit to the grid
//     + fairness · [ (1/n) Σ_j ∫|S_uu(u, v_j)|² du + (1/m) Σ_i ∫|S_vv(u_i, v)|² dv ]   bending of the
//     + fairness² · ∫∫ |S_uuvv|² du dv                                     data's rows and columns
//     + knot_spread · scale · (mean_s (gap / h_s)² over the u spans + the same over the v spans)
//
// Why this fairness: with it the normal equations are the Kronecker product K_u ⊗ K_v of two curve
// systems (K = collocation Gram / samples + fairness · ∫N''N''), so the control points are solved exactly
// by curve-sized solves, row by row then column by column, and for fixed v knots E is, up to a term
// free of the u knots, a sum of cv curve energies (curve_fit_energy) on virtual data Z = P M L_v⁻ᵀ / n
// (K_v = L_v L_vᵀ): the u-knot gradient is theirs summed, exactly; the v-knot gradient likewise with the
// roles swapped. Integrals per knot span as the curves do (span_quadrature). The f² term is the
// Kronecker product's own; with the default fairness (1e-12) it is negligible but it is included.
#include <Eigen/Core>
#include <vector>

namespace cadnurbs {

struct GridSamples {                     // the data to fit, at FIXED parameters
  std::vector<double> u;                 // m values, increasing, in [0, 1]
  std::vector<double> v;                 // n values, increasing, in [0, 1]
  std::vector<Eigen::Vector3d> points;   // m · n, points[i + j · m] at (u[i], v[j]) (VRML order: u fastest)
};

struct SurfaceFitEnergyTerms {
  double fairness = 0;
  double knot_spread = 0;
  double minimum_gap = 0;  // spans at most 4 gaps long integrate with Simpson's rule
  double scale = 1;        // the energy unit of the spread term (the caller's start fit energy)
};

struct SurfaceFitEvaluation {
  double energy = 0;
  double data_energy = 0;      // the first term alone
  double fairness_energy = 0;  // the two bending terms, fairness included
  std::vector<Eigen::Vector3d> control_points;  // the optimal ones for these knots, u_count · v_count, u fastest
  std::vector<double> u_knot_gradient;          // dE/du_i for every u knot (ends included; callers hold them)
  std::vector<double> v_knot_gradient;
};

// u_knots, v_knots: clamped vectors of u_count + u_order and v_count + v_order values whose domain
// spans are all non-empty. Gradients only when `with_gradient`. Returns energy = +infinity when a
// direction's system is singular (too few samples to fix its control points). Checks nothing else (the
// fitter's job).
SurfaceFitEvaluation evaluate_surface_fit_energy(const GridSamples& grid, int u_order, int v_order,
                                                 const std::vector<double>& u_knots, const std::vector<double>& v_knots,
                                                 const SurfaceFitEnergyTerms& terms, bool with_gradient);

}  // namespace cadnurbs
