#pragma once
// Least-squares fits of clamped uniform cubic B-splines on [0, 1] with their
// boundary control points held (internal to analysis/subd_nurbs): how
// subd_to_nurbs fits the patches around extraordinary points while keeping
// every shared side identical to its neighbour's.
#include <Eigen/Core>
#include <vector>

namespace cadnurbs::subd_nurbs {

// 0,0,0,0, 1/spans, ..., 1,1,1,1: spans + 7 values for spans + 3 control
// points.
std::vector<double> uniform_cubic_knots(int spans);

// The curve's spans + 3 control points nearest (least squares) to samples[a] at
// params[a], its first and last held at `first` and `last`. params must include
// enough points in every span (Schoenberg-Whitney).
std::vector<Eigen::Vector3d>
fit_cubic_curve(int spans, const std::vector<double> &params,
                const std::vector<Eigen::Vector3d> &samples,
                const Eigen::Vector3d &first, const Eigen::Vector3d &last);

// The surface's (spans + 3)^2 control points, index i + (spans + 3) j (u
// fastest), nearest (least squares) to samples[a + params.size() b] at
// (params[a], params[b]); the points of `points` on the grid's four boundary
// rows are held as given, the others replaced. The tensor grid of samples makes
// the problem separable: two small solves instead of one with every interior
// point.
void fit_cubic_surface_interior(int spans, const std::vector<double> &params,
                                const std::vector<Eigen::Vector3d> &samples,
                                std::vector<Eigen::Vector3d> &points);

} // namespace cadnurbs::subd_nurbs
