#pragma once
// Least-squares NURBS curve fitting with automatic knots (seed 003) and hierarchical local refinement
// (seed 002), for data at fixed parameters such as an animation path's keys at their fractions.
//
// How: for given knots and weights the control points are solved exactly (curve_fit_energy: banded
// normal equations of fit + fairness); the interior knots and the weights are then moved by
// Polak-Ribière conjugate gradient on that reduced energy, its gradient taken over the rational Bézier
// re-parametrisation, with the hard constraints kept by the line search (knots at least
// minimum_knot_gap apart, weights at least minimum_weight) as seed 003 §5.2 describes.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/nurbs_curve.hpp"

namespace cadnurbs {

struct CurveSamples {                      // the data to fit, at FIXED parameters
  std::vector<double> parameters;          // non-decreasing, in [0, 1]
  std::vector<Eigen::Vector3d> points;     // one per parameter
};

enum class InitialKnots {
  averaged,  // Piegl & Tiller (9.69): each interior knot a weighted mean of the sample parameters
  uniform,   // equally spaced on [0, 1], whatever the data
};

struct CurveFitOptions {
  int order = 4;                           // degree + 1
  double fairness = 1e-12;                 // weight of ∫_0^1 |C''|² dt against the mean squared error
                                           // (both lengths squared; larger values visibly flatten fast paths)
  bool optimise_knots = true;              // false: the initial knots, control points (and weights) only
  bool optimise_weights = true;            // false: polynomial (all weights 1)
  double minimum_knot_gap = 1e-4;          // relative to the domain [0, 1]
  int max_iterations = 40;                 // conjugate-gradient iterations per fit
  InitialKnots initial_knots = InitialKnots::averaged;
  double knot_spread = 1e-3;               // the small term keeping knots apart (relative to the start's energy)
  double weight_pull = 1e-3;               // the small term keeping weights near 1 (same unit)
  double minimum_weight = 0.05;            // hard floor of the weights
};

struct CurveFit {
  NurbsCurve curve;                        // dimension 3, clamped knots on exactly [0, 1]
  double max_error = 0;                    // max |C(t_i) - P_i| over the samples
  double rms_error = 0;
  int iterations = 0;                      // CG iterations in all
  int refinements = 0;                     // fit_curve_within: rounds of local knot insertion
};

// Fits `control_points` control points (order <= control_points <= the number of distinct sample
// parameters) to the samples: energy = mean squared error + fairness + the two small terms; starts
// from the initial knots (averaged by default), weights 1. Refuses (std::invalid_argument, saying
// why) samples that are empty, of unequal counts, not finite, not non-decreasing in [0, 1], too few
// for the control points, or a knot gap too large for the spans.
CurveFit fit_curve(const CurveSamples& samples, int control_points, const CurveFitOptions& options);

// Hierarchical local refinement (seed 002): starts with options.order + 1 control points; each round
// takes the current knots and weights, solves the control points, and runs the minimisation unless
// that start is already within tolerance; while some sample is farther than `tolerance`, it inserts a
// knot at the middle of every span that holds such a sample (and only there) and goes on from the
// refined curve. When the next round would need more control points than there are distinct sample
// parameters, one last fit with exactly that many is tried. Returns the first fit with every sample
// within tolerance (iterations summed over the rounds). Refuses (std::invalid_argument) what
// fit_curve refuses, tolerance <= 0, and data that cannot be met: the last fit still beyond the
// tolerance, or a span at fault too short to split at the minimum knot gap.
CurveFit fit_curve_within(const CurveSamples& samples, double tolerance, const CurveFitOptions& options);

// Empty when `curve` keeps the fitter's hard constraints: clamped knots on exactly [0, 1], interior
// spans at least minimum_gap long (a relative 1e-9 of round-off allowed), weights all > 0; otherwise a
// sentence naming the first fault. Checked on every iteration in a debug build.
std::string fit_constraint_fault(const NurbsCurve& curve, double minimum_gap);

}  // namespace cadnurbs
