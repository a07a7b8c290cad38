#pragma once
// The area of everything a scene draws, in world coordinates: what a part's surface measures whatever
// form its faces take (trimmed NURBS, exact polygons, triangles), so that two forms can be compared.
#include "core/scene.hpp"

namespace cadnurbs {

// Per shape: trimmed NURBS by trimmed_surface_area (to `relative_tolerance`) with the control points
// placed by the shape's world transform (exact for rigid motions and uniform scales: the control net
// moves with the surface); meshes and polygon sets by the area of their placed triangles; curves 0.
// Refuses (GeometryError) what trimmed_surface_area refuses.
double shape_area(const Shape& shape, const Eigen::Affine3d& world, double relative_tolerance = 1e-9);

// The sum over every shape of the scene.
double scene_area(const Scene& scene, double relative_tolerance = 1e-9);

}  // namespace cadnurbs
