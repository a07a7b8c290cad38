#pragma once
// Plain 2D polygon measures shared by trimming loops (core), planar faces and convex merging (analysis)
// and loop orientation (formats/brep).
#include <Eigen/Core>
#include <vector>

namespace cadnurbs {

// Shoelace area of the closed polygon (last point != first): positive when counter-clockwise.
double polygon_signed_area(const std::vector<Eigen::Vector2d>& polygon);

// b turns left, or goes straight within `tolerance` (a distance off the line a-c), on the way a -> b -> c.
// Also true when a and c coincide.
bool convex_corner(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c, double tolerance);

}  // namespace cadnurbs
