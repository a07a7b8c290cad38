#pragma once
// T-junctions closed by splitting: where a vertex of the mesh's boundary lies on a boundary edge of
// another triangle (a planar face's polygon beside a curved face's tessellation, which samples their
// shared straight edge at points of its own), that triangle is split into a fan at those vertices. The
// surface does not move (each new triangle lies in the old one, and the vertices lie on the edge within
// `tolerance`), but the mesh becomes closed where it was only geometrically so.
//
// In: a mesh welded by position (weld_exact), tolerance >= 0 (a distance from the edge's segment).
// Out: the same vertices (plus, for a triangle split on two or three edges, one at its centroid), each
// split triangle replaced by the triangles of its fan; corner normals are not kept; `splits` (optional)
// gets the vertices inserted into edges.
// Boundary edges and vertices are found once: an edge made by a split is not searched again.
#include "core/triangle_mesh.hpp"

namespace cadnurbs {

TriangleMesh split_t_junctions(const TriangleMesh& mesh, double tolerance, long* splits = nullptr);

}  // namespace cadnurbs
