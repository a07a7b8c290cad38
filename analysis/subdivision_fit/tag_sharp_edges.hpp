#pragma once
// Crease and corner tags read off a coarse mesh's own angles: the second start of a Loop fit, a plain
// quadric decimation (which spends its vertices where the error is, with no regard to creases) tagged
// where it is sharp itself.
#include "core/subdivision_control_mesh.hpp"

namespace cadnurbs {

// Takes a triangle mesh and a sharp angle in radians; returns it as a Loop control mesh (positions and
// triangles unchanged) with these tags:
// - crease_edges: every edge with exactly two faces whose normals differ by the sharp angle or more;
// - corner_vertices: every vertex with exactly two sharp edges (tagged, boundary or non-manifold) that
//   turn by the sharp angle or more (3+ sharp edges make a corner without a tag), as
//   decimate_control_mesh tags the corners it locks.
// A degenerate face (no normal) makes none of its edges sharp. Refuses (std::invalid_argument) an
// index out of range.
SubdivisionControlMesh tag_sharp_edges(const TriangleMesh& mesh, double sharp_angle_radians);

}  // namespace cadnurbs
