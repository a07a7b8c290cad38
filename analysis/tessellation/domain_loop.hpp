#pragma once
// For the loop of an untrimmed face (core's domain_loop, internal): whether two opposite sides are one
// curve in 3D (the seam of a closed direction), so that the seam is sampled once and the mesh closes there.
#include <Eigen/Core>

#include "analysis/eval/surface_evaluator.hpp"
#include "core/trimmed_surface.hpp"

namespace cadnurbs::tessellation {

// True when the (u,v) lines a0-a1 and b0-b1 map to the same 3D curve, point for point: 17 evenly
// spaced pairs of points within `tolerance` of each other.
bool sides_coincide(const SurfaceEvaluator& e, const Eigen::Vector2d& a0, const Eigen::Vector2d& a1,
                    const Eigen::Vector2d& b0, const Eigen::Vector2d& b1, double tolerance);

}  // namespace cadnurbs::tessellation
