#pragma once
// Fewer control points for the same shape: knot removal (core/knot_removal) on every surface and
// 3D curve of a scene, each moving by at most a given distance in world coordinates.
// Trimming loops are left as they are: they live in the surface's (u,v) domain, which knot removal
// keeps, so they stay valid, and their 3D images move with the surface, by at most the same distance.
// Two faces along a shared edge may therefore part by twice that distance; callers pick it so that
// the gap stays within what sewing bridges (see simplified_scene in converters/scene_preparation).
#include "core/scene.hpp"

namespace cadnurbs {

struct SimplifyReport {
  long knots_removed = 0;
  long control_points_before = 0, control_points_after = 0;  // of the surfaces and 3D curves
  int surfaces_changed = 0, curves_changed = 0;
  double curve_deviation = 0;  // largest distance between a placed 3D curve and its simplified form,
                               // sampled at the same parameters (32 per knot span of the input)
};

// The scene with every trimmed surface's net and every NurbsCurve (3D) simplified by remove_knots
// within `max_move` (world units): each shape's tolerance is max_move divided by the largest
// stretch of its world transform (the operator norm of its linear part), so that the placed shape
// moves by at most max_move. Equal nets whose tolerances agree to 1e-9 (copies of a repeated part) give
// equal results. Meshes and polygon sets pass through. Refuses (std::invalid_argument) a
// max_move that is not a positive number.
Scene simplify_scene(const Scene& scene, double max_move, SimplifyReport* report = nullptr);

}  // namespace cadnurbs
