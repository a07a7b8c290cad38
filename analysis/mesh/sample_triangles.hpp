#pragma once
// Sample points on a triangle mesh for distance measurement: every vertex once, then on every
// triangle the points of a regular lattice (n+1)(n+2)/2 without its corners, n chosen so that lattice
// steps are at most `spacing` (n in [3, 64]).
#include "core/triangle_mesh.hpp"

namespace cadnurbs {

// With `area_weights`, also the area each point stands for (same order as the points): a triangle's
// area shared equally among its (n+1)(n+2)/2 lattice points, corners included, so a vertex gets a
// share from each of its triangles. The weights sum to the mesh's area, and sum(w d^2) / sum(w) is
// the mean of d^2 over the surface however unevenly the points lie (at least 7 on a small triangle,
// at most 2,145 on a large one).
std::vector<Eigen::Vector3d> sample_triangles(const TriangleMesh& mesh, double spacing,
                                              std::vector<double>* area_weights = nullptr);

// A third of the mean edge length: the default sample spacing for a mesh.
double default_sample_spacing(const TriangleMesh& mesh);

}  // namespace cadnurbs
