#pragma once
// Point inversion on a NURBS surface: the (u,v) of the surface point nearest to a 3D point, by Newton
// iteration on |S(u,v) - p|^2 (Piegl & Tiller, The NURBS Book, 6.1). Core's own, on surface_derivatives
// (analysis/eval's project_to_surface does the same over its faster SurfaceEvaluator, which core may
// not use).
#include <Eigen/Core>

#include "core/nurbs_surface.hpp"

namespace cadnurbs {

// Local: Newton from `start` (clamped into the domain): the full Hessian where it is positive definite,
// Gauss-Newton otherwise; each step halved until the distance drops; (u,v) kept in the domain (a step
// that leaves it across a side moves along that side instead); at most 30 iterations. Returns the
// (u,v) reached: a local minimum of the distance near `start` (the global one only from a good start),
// or where the iterations stopped. Refuses nothing; a non-finite p gives back the clamped start.
Eigen::Vector2d nearest_surface_parameter(const NurbsSurface& surface, const Eigen::Vector3d& p,
                                          const Eigen::Vector2d& start);

// Global, as far as a grid sees: a grid of surface points (3 per knot span in each direction, at least
// 8 per direction, domain ends included); Newton from the grid's local minima (nearest first, at most
// 4: on a closed surface both sides of the seam are minima); the nearest result. A point nearer to a
// part of the surface that the grid misses entirely (a fold narrower than a grid cell) may go to a
// local minimum.
Eigen::Vector2d nearest_surface_parameter(const NurbsSurface& surface, const Eigen::Vector3d& p);

}  // namespace cadnurbs
