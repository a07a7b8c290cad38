#pragma once
// Triangles merged into convex polygons (Hertel & Mehlhorn 1983: drop every inessential diagonal of a
// triangulation). A planar face with holes has to be triangulated for an IndexedFaceSet, whose faces are
// convex polygons; merged back into the largest convex pieces, it needs about half the indices.
#include <Eigen/Core>
#include <array>
#include <vector>

namespace cadnurbs {

// `triangles` (counter-clockwise, indices into `points`, edge-connected where they share two corners)
// merged greedily across shared edges while both corners where the pieces meet stay convex (turning
// left, or straight within `tolerance`, a distance). Returns counter-clockwise polygons covering exactly
// the triangles' union; each is convex. At worst four times the minimum number of convex pieces.
std::vector<std::vector<int>> merge_convex_polygons(const std::vector<Eigen::Vector2d>& points,
                                                    const std::vector<std::array<int, 3>>& triangles,
                                                    double tolerance);

}  // namespace cadnurbs
