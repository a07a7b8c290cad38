#pragma once
// Analytic test shapes as exact rational NURBS, with their exact distance functions.
#include <Eigen/Core>

#include "core/scene.hpp"

namespace cadnurbs::test {

// Quarter cylinder of `radius` about Z from z = 0 to `height` (u along the arc, v along Z).
TrimmedSurface quarter_cylinder(double radius, double height);
double distance_to_cylinder(const Eigen::Vector3d& p, double radius);

// Whole sphere about the origin: u a full circle (4 rational arcs), v a half meridian from the south
// pole to the north pole (2 arcs); the v sides are poles, the u sides a seam. Untrimmed.
TrimmedSurface sphere(double radius);
double distance_to_sphere(const Eigen::Vector3d& p, double radius);

// The same sphere with an explicit trim loop around its domain and edge ids: south pole `first`,
// seam `first + 1` (used twice), north pole `first + 2`.
TrimmedSurface sphere_with_edges(double radius, int first);

// A quarter x quarter patch of the torus of radii (major, minor) about Z.
TrimmedSurface torus_patch(double major, double minor);
double distance_to_torus(const Eigen::Vector3d& p, double major, double minor);

// The square [0, size]^2 at z = 0 (bilinear, (u,v) in [0,1]^2) trimmed by a circle of `outer`
// radius with a circular hole of `inner` radius (fractions of size, centred): an annulus.
TrimmedSurface trimmed_square(double size, double outer, double inner);

// A 2D full circle (four rational quadratic arcs) of radius r about c, counter-clockwise.
NurbsCurve circle_2d(const Eigen::Vector2d& c, double r);

}  // namespace cadnurbs::test
