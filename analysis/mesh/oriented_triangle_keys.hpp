#pragma once
// Triangles compared by where their corners are, whatever the vertex numbering: each triangle becomes
// its three corner positions (9 numbers), in the rotation that is lexicographically smallest (the
// orientation is kept; with two corners at one place this still names one rotation), and the list is
// sorted. Two meshes hold the same oriented triangles at
// the same places exactly when their keys are equal; codecs that renumber vertices and reorder
// triangles (Draco, .cnb's traversal coding) are checked this way.
#include <array>
#include <vector>

#include <Eigen/Core>

namespace cadnurbs {

using TriangleKey = std::array<double, 9>;

// One key per triangle of `triangles` (indices into `positions`), sorted.
std::vector<TriangleKey> oriented_triangle_keys(const std::vector<Eigen::Vector3d>& positions,
                                                const std::vector<std::array<int, 3>>& triangles);

}  // namespace cadnurbs
