#pragma once
// Point inversion on a curve: the parameter of the point of a NURBS curve nearest a given point, by
// Newton's iteration on (C(t) - p) . C'(t) = 0 (Piegl & Tiller 6.1) from the nearest of a few samples
// per knot span, kept inside the domain. Global only as far as the samples are: a curve that comes back
// within a sample spacing of p may give the other branch.
#include <Eigen/Core>

#include "core/nurbs_curve.hpp"

namespace cadnurbs {

// Takes a valid curve (2D or 3D) and a point. Returns t in the curve's domain.
double nearest_curve_parameter(const NurbsCurve& curve, const Eigen::Vector3d& p);

}  // namespace cadnurbs
