#pragma once
// Least-squares fits of clamped cubic B-splines on [0, 1] with their boundary control points held (internal
// to analysis/subd_nurbs): how subd_to_nurbs fits the patches around extraordinary points while keeping
// every shared side identical to its neighbour's.
#include <Eigen/Core>
#include <vector>

namespace cadnurbs::subd_nurbs {

// Clamped cubic knots graded toward both ends: 0,0,0,0, 2^-levels, ..., 1/4, 1/2, 3/4, ..., 1 - 2^-levels,
// 1,1,1,1 (2 levels spans, levels >= 1). Symmetric, so a side read backwards has the same knots. The
// limit surface of a quad with an extraordinary corner is bicubic on the dyadic squares that avoid the
// corner, so on every span but the corner ones this space holds it exactly (a uniform grid of 2^levels
// spans would hold no more there, with far more points). `halved` adds the middle of every span but the end
// ones (3/8, 3/16, ..., and 1 - them): where Rhino's sector coefficients shape the limit (a tagged point's
// neighbours at every level are special too) it is bicubic on squares of level j only from 2 of them away
// from the corner on, which these knots follow.
std::vector<double> graded_cubic_knots(int levels, bool halved = false);

// Parameters for the fit's samples: `per_span` + 1 in every span of `knots` (ends included) and
// `end_steps` more, geometric, inside each end span, where the fit has to work.
std::vector<double> sample_params(const std::vector<double>& knots, int per_span, int end_steps);

// The curve's knots.size() - 4 control points nearest (least squares) to samples[a] at params[a], its
// first and last held at `first` and `last`. params must put enough points in every span
// (Schoenberg-Whitney).
std::vector<Eigen::Vector3d> fit_cubic_curve(const std::vector<double>& knots, const std::vector<double>& params,
                                             const std::vector<Eigen::Vector3d>& samples, const Eigen::Vector3d& first,
                                             const Eigen::Vector3d& last);

// The surface's c^2 control points (c = knots.size() - 4, the same knots both ways), index i + c j (u
// fastest), nearest (least squares) to samples[a + params.size() b] at (params[a], params[b]); the points
// of `points` on the grid's four boundary rows are held as given, the others replaced. The tensor grid of
// samples makes the problem separable: two small solves instead of one with every interior point.
void fit_cubic_surface_interior(const std::vector<double>& knots, const std::vector<double>& params,
                                const std::vector<Eigen::Vector3d>& samples, std::vector<Eigen::Vector3d>& points);

}  // namespace cadnurbs::subd_nurbs
