#pragma once
// Least-squares fitting of gridded data by a tensor-product B-spline surface with automatic knots in u
// and v (seed 003) and hierarchical local refinement (seed 002): refitting a dense B-spline surface
// sampled on a grid, or a height field. Polynomial only (no weights): gridded data from a polynomial
// surface or a height field needs none, and weights would break the row-by-column separation below.
//
// How: for given knots the control points are solved exactly (surface_fit_energy: the normal equations
// separate into curve solves, row by row then column by column); the interior u and v knots are moved
// together by Polak-Ribière conjugate gradient on that reduced energy, its gradient exact (the curve
// energies' gradients on whitened data), under the curves' hard constraints (knot_gap_constraints:
// knots at least minimum_knot_gap apart, the ends 0 and 1 fixed), kept by the line search.
#include <string>

#include "analysis/fitting/fit_curve.hpp"
#include "analysis/fitting/surface_fit_energy.hpp"
#include "core/nurbs_surface.hpp"

namespace cadnurbs {

struct SurfaceFitOptions {
  int u_order = 4, v_order = 4;      // degree + 1 in each direction
  double fairness = 1e-12;           // weight of the bending terms against the mean squared error
  bool optimise_knots = true;        // false: the initial knots, control points only
  double minimum_knot_gap = 1e-4;    // relative to the domain [0, 1], in both directions
  int max_iterations = 40;           // conjugate-gradient iterations per fit (u and v knots together)
  InitialKnots initial_knots = InitialKnots::averaged;
  double knot_spread = 1e-3;         // the small term keeping knots apart (relative to the start's energy)
};

struct SurfaceFit {
  NurbsSurface surface;              // polynomial, clamped knots on exactly [0, 1] x [0, 1]
  double max_error = 0;              // max |S(u_i, v_j) - P_ij| over the grid
  double rms_error = 0;
  int iterations = 0;                // CG iterations in all
  int refinements = 0;               // fit_surface_within: rounds of local knot insertion
};

// Fits u_control_points x v_control_points control points (order <= count <= that direction's
// parameter count) to the grid: energy = mean squared error + fairness + the spread term; starts from
// the initial knots (averaged by default). Refuses (std::invalid_argument, saying why) a grid without
// parameters, points not m · n or not finite, parameters not increasing in [0, 1], orders outside
// 2..16, too few parameters for the control points, or a knot gap too large for the spans.
SurfaceFit fit_surface(const GridSamples& grid, int u_control_points, int v_control_points,
                       const SurfaceFitOptions& options);

// Hierarchical local refinement (seed 002): starts with order + 1 control points each way; each round
// solves the control points for the current knots and runs the minimisation unless that start is
// already within tolerance. While some grid point is farther than `tolerance`, it inserts a knot at the
// middle of every span at fault, and only there: the u span of such a point when fitting its grid row
// alone in u (v resolved exactly) misses it by more than tolerance / 2, the v span likewise by its
// column, the worse of the two when neither does. Returns the first fit with every grid point within
// tolerance (iterations summed). Refuses (std::invalid_argument) what fit_surface refuses, tolerance
// <= 0, and data that cannot be met: a span at fault too short to split at the minimum knot gap, or a
// direction needing more control points than it has parameters.
SurfaceFit fit_surface_within(const GridSamples& grid, double tolerance, const SurfaceFitOptions& options);

}  // namespace cadnurbs
