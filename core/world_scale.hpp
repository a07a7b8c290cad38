#pragma once
// How much a placement stretches lengths: a point moved by δ in a node's own coordinates moves by at most
// transform_scale(world)·δ in the world. Bounds made in a shape's own coordinates (a tessellation's
// certificate, a quantisation's step) become world bounds through it.
#include <Eigen/Geometry>

#include "core/scene.hpp"

namespace cadnurbs {

// Largest singular value of the linear part of `transform` (its operator norm).
double transform_scale(const Eigen::Affine3d& transform);

// The largest transform_scale of the world transform of every node that holds shapes; 1 for a scene
// without shapes.
double largest_world_scale(const Scene& scene);

}  // namespace cadnurbs
