#pragma once
// The loop of an untrimmed face (internal): its whole domain as four sides, and whether two opposite
// sides are one curve in 3D (the seam of a closed direction), so that the seam is sampled once and
// the mesh closes there.
#include <Eigen/Core>

#include "analysis/surface_evaluator.hpp"
#include "core/trimmed_surface.hpp"

namespace cadnurbs::tessellation {

// A rectangle loop around the whole domain, counter-clockwise: sides (v0 side, u1 side, v1 side,
// u0 side), each a two-point polyline.
TrimLoop domain_loop(const NurbsSurface& surface);

// True when the (u,v) lines a0-a1 and b0-b1 map to the same 3D curve, point for point: 17 evenly
// spaced pairs of points within `tolerance` of each other.
bool sides_coincide(const SurfaceEvaluator& e, const Eigen::Vector2d& a0, const Eigen::Vector2d& a1,
                    const Eigen::Vector2d& b0, const Eigen::Vector2d& b1, double tolerance);

}  // namespace cadnurbs::tessellation
