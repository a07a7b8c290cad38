#pragma once
// From derivatives of a homogeneous (w*P, w) curve or surface to derivatives of the rational one
// (Piegl & Tiller A4.2 and A4.4). Kept apart so curve and surface evaluation share it.
#include <Eigen/Core>
#include <vector>

namespace cadnurbs {

// homogeneous[k] = k-th derivative of (wP, w); returns the k-th derivatives of P.
std::vector<Eigen::Vector3d> rational_curve_derivatives(const std::vector<Eigen::Vector4d>& homogeneous);

// homogeneous[k][l] = d^{k+l}/du^k dv^l of (wP, w); returns the same derivatives of P, k + l <= d.
std::vector<std::vector<Eigen::Vector3d>> rational_surface_derivatives(
    const std::vector<std::vector<Eigen::Vector4d>>& homogeneous);

}  // namespace cadnurbs
