#pragma once
// The limit surface of a Loop control mesh as a triangle mesh: the control mesh refined k times,
// each vertex then moved to its point on the limit surface. Everything is linear in the control
// points, so the result is a sparse matrix (limit points = matrix * control points); the fitting
// solves through it and the viewers get its product.
#include "analysis/subdivision/refinement.hpp"

namespace cadnurbs {

struct SubdivisionLimitMesh {
  ControlMeshTopology level;            // the k-th refinement's topology
  LimitStencils limit_from_control;  // rows: level-k vertices; columns: control vertices
  int coarser_vertex_count = 0;     // level k-1's vertices, which are level k's first ones (0 for k = 0)
};

// Limit-point masks for a level's vertices (rows and columns: that level's vertices):
// - smooth and dart vertices: Loop's, 1 - n w itself and w each neighbour, w = 1 / (3 / (8 beta) + n)
//   (exact at smooth vertices; at a dart, whose one sharp edge refines by the midpoint rule, an
//   approximation whose error shrinks by about 4 with each level before it);
// - crease vertices: 2/3 itself, 1/6 each sharp neighbour (the point of the uniform cubic B-spline);
// - corners: themselves.
LimitStencils limit_stencils(const ControlMeshTopology& level);

// Takes a control mesh's topology and a level count 0..8; returns level k's triangles and the map
// from control points to their limit points. Triangle T of the result lies in control triangle T >> 2k.
// Refuses (std::invalid_argument) a level count outside 0..8 and what control_mesh_edges refuses.
SubdivisionLimitMesh subdivision_limit_mesh(const ControlMeshTopology& control, int levels);

// The limit mesh's positions for given control points (rows of `control_points` = control vertices).
TriangleMesh evaluate_limit_mesh(const SubdivisionLimitMesh& limit, const std::vector<Eigen::Vector3d>& control_points);

}  // namespace cadnurbs
