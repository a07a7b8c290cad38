#pragma once
// The limit surface over some control triangles only, as the rows of the whole limit map that belong
// to them. A Loop patch depends only on the control triangles that share a vertex with its own (its
// 1-ring, extraordinary vertices and tags included): every refined vertex in or next to the patch is
// made from the patch's corners (vertex rules, whose valence and sharp edges are all in that ring)
// and from edges at those corners (edge rules, whose opposite vertices are too). So the map built
// from that sub-mesh alone, with its border made sharp by being a border, gives the patch the same
// rows; only the ring's outer patches, which are dropped, come out wrong. A connectivity change can
// then be judged at a cost that grows with the region it changes, not with the mesh.
#include "analysis/subdivision/limit_surface.hpp"

namespace cadnurbs {

struct LimitPatches {
  // 4^k triangles per region triangle, in the region's order; within one region triangle in the
  // order and with the corner order of subdivision_limit_mesh's triangles 4^k t .. 4^k (t + 1) - 1.
  std::vector<std::array<int, 3>> triangles;
  // Rows: the corners `triangles` use, nothing else; columns: the whole control mesh's vertices.
  LimitStencils limit_from_control;
};

// Takes a control mesh's topology, the triangles at each of its vertices (vertex_triangles[v]: the
// indices of the triangles that use v), the control triangles wanted (each once) and a level count
// 0..8. Returns their limit patches, equal to subdivision_limit_mesh's rows for them up to rounding. Cost:
// a refinement of the region's 1-ring sub-mesh, plus one pass over the tag lists.
// Refuses (std::invalid_argument) a level count outside 0..8, a triangle index out of range or
// repeated, and what control_mesh_edges refuses in the sub-mesh.
LimitPatches limit_patches(const ControlMeshTopology& control, const std::vector<std::vector<int>>& vertex_triangles,
                                    const std::vector<int>& region, int levels);

}  // namespace cadnurbs
