#pragma once
// A Loop control mesh from a dense triangle mesh: quadric-error decimation (Garland & Heckbert 1997,
// OpenMesh's Decimater) with the sharp features of the input kept and tagged (Hoppe et al. 1994 start
// their fit the same way, from a simplified mesh with the creases marked).
#include "core/subdivision_control_mesh.hpp"

namespace cadnurbs {

struct DecimationReport {
  int input_vertices = 0, input_triangles = 0;
  int skipped_triangles = 0;  // not representable as a manifold mesh (OpenMesh refused them)
  int sharp_input_edges = 0;  // at or above the sharp angle, or boundary
  int locked_corners = 0;     // vertices whose 2 sharp edges turn by the sharp angle
};

// Takes a welded mesh (weld_vertices), a target vertex count >= 4, and a sharp angle in radians
// (dihedral angle between face normals at or above which an edge is a crease; a negative angle turns
// feature keeping off: plain quadric decimation, no tags). Returns the decimated mesh:
// - with features on: a vertex on a crease only collapses along it (so creases stay and keep their
//   course, and their tags pass on to the edges that survive a collapse), a crease vertex whose two
//   sharp edges turn by the sharp angle is locked, and no collapse may turn a face normal by more
//   than 60 degrees; the surviving sharp interior edges are tagged crease_edges, the locked vertices
//   corner_vertices (3+ sharp edges make a corner without a tag);
// - the vertex count is the target, or more when the locked corners and crease ends leave no legal
//   collapse (the count returned is what there is);
// - positions are a subset of the input's (half-edge collapses, no new points).
// Refuses (std::invalid_argument) a target below 4, a mesh without triangles, a kept index out of range.
// `keep` lists input vertices that must stay (locked: where an earlier fit stayed too far).
// `distance_guard` > 0: no collapse may leave a removed input vertex farther than it from the mesh
// (OpenMesh's ModHausdorffT), which stops the decimation early when the target needs more; quadrics
// alone let a cup's rim close over it, as all of the lid's corners lie in the rim's plane
// (decimate_within_distance searches for the guard that reaches the target).
SubdivisionControlMesh decimate_control_mesh(const TriangleMesh& welded, int target_vertices, double sharp_angle_radians,
                                      DecimationReport* report = nullptr, const std::vector<int>& keep = {},
                                      double distance_guard = 0);

}  // namespace cadnurbs
