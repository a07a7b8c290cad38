#pragma once
// Triangulation of a planar region bounded by closed polygons (outer boundaries and holes, even-odd
// rule), by CGAL's constrained Delaunay triangulation; optional extra points inside.
#include <Eigen/Core>
#include <array>
#include <vector>

namespace cadnurbs {

struct PlanarTriangulation {
  // The input points in order (loops[0], loops[1], ..., interior_points), then any point where two
  // loop edges crossed. Coincident input points leave some of them unused.
  std::vector<Eigen::Vector2d> points;
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise
};

// `loops`: closed polygons (last point != first), any orientation; `interior_points`: extra vertices
// (left out when outside the region). Throws std::runtime_error when a loop has fewer than 3 points.
PlanarTriangulation triangulate_polygon(const std::vector<std::vector<Eigen::Vector2d>>& loops,
                                        const std::vector<Eigen::Vector2d>& interior_points = {});

}  // namespace cadnurbs
