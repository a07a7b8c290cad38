#pragma once
// The normal of one STL facet, shared by the reader and the writer.
#include <Eigen/Core>

namespace cadnurbs {

// Takes the corners a, b, c of a triangle; returns the unit normal by the right-hand rule
// (normalized (b - a) x (c - a)), or the zero vector when the triangle is degenerate (the cross
// product is zero or not finite). Refuses nothing.
Eigen::Vector3d facet_normal(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

}  // namespace cadnurbs
