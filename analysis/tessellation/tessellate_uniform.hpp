#pragma once
// Uniform tessellation as in seed 000: every non-empty knot span divided into a fixed number of
// steps, normals from the cross product of the partial derivatives. Trimmed surfaces keep the grid
// points inside their loops and triangulate them together with the sampled loops (CGAL CDT).
// No deviation bound: that is tessellate_to_deviation's job.
#include "core/scene.hpp"

namespace cadnurbs {

// The (u, v) parameters of the grid: each non-empty span of `knots` in `steps` equal parts.
std::vector<double> uniform_parameters(const std::vector<double>& knots, int order, int count, int steps);

// Triangles of one (trimmed) surface with per-corner normals, in the surface's own coordinates.
TriangleMesh tessellate_uniform(const TrimmedSurface& surface, int steps_per_span);

// The scene with every NURBS surface replaced by its tessellation (names, colours, tree kept).
Scene tessellate_uniform(const Scene& scene, int steps_per_span);

}  // namespace cadnurbs
