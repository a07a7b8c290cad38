#pragma once
// Point inversion on a curve: the parameter of the point of a NURBS curve nearest a given point, by
// Newton's iteration on (C(t) - p) . C'(t) = 0 (Piegl & Tiller 6.1) from the nearest of a few samples
// per knot span, kept inside the domain. Global only as far as the samples are: a curve that comes back
// within a sample spacing of p may give the other branch.
#include <Eigen/Core>
#include <vector>

#include "core/nurbs_curve.hpp"

namespace cadnurbs {

// Takes a valid curve (2D or 3D) and a point. Returns t in the curve's domain.
double nearest_curve_parameter(const NurbsCurve& curve, const Eigen::Vector3d& p);

// Every pass of the curve within `within` of p: Newton from each local minimum of the distance at 64
// samples per knot span, ascending (passes closer than a sample spacing may merge into one).
std::vector<double> curve_parameters_near(const NurbsCurve& curve, const Eigen::Vector3d& p, double within);

}  // namespace cadnurbs
