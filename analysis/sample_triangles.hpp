#pragma once
// Sample points on a triangle mesh for distance measurement: every vertex once, then on every
// triangle the points of a regular lattice (n+1)(n+2)/2 without its corners, n chosen so that lattice
// steps are at most `spacing` (n in [3, 64]).
#include "core/triangle_mesh.hpp"

namespace cadnurbs {

std::vector<Eigen::Vector3d> sample_triangles(const TriangleMesh& mesh, double spacing);

// A third of the mean edge length: the default sample spacing for a mesh.
double default_sample_spacing(const TriangleMesh& mesh);

}  // namespace cadnurbs
