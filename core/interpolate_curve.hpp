#pragma once
// Global curve interpolation (Piegl & Tiller, The NURBS Book, 9.2.1): the B-spline curve through given
// points at given parameters.
#include <Eigen/Core>
#include <vector>

#include "core/nurbs_curve.hpp"

namespace cadnurbs {

// The polynomial B-spline of `degree` (lowered to points - 1 when there are fewer points) that passes
// through points[k] at parameters[k], exactly at the ends (its first and last control points are the
// first and last points). Knots by averaging the parameters (P&T eq. 9.8), clamped; the domain is
// [parameters.front(), parameters.back()]; one control point per point. Solved as the banded system it
// is, without pivoting (P&T 9.2.1: the matrix is totally positive), in O(n degree^2). `dimension` (2 or
// 3) is stored as is; 2D points must have z = 0. Refuses (GeometryError) fewer than 2 points, sizes
// that differ, degree < 1, parameters not strictly increasing, non-finite input.
NurbsCurve interpolate_curve(const std::vector<Eigen::Vector3d>& points, const std::vector<double>& parameters,
                             int degree, int dimension);

}  // namespace cadnurbs
