#pragma once
// Consistent face orientation: neighbouring triangles run their shared edge in opposite directions, and
// closed surfaces face outward. An STL file's winding is whatever its exporter wrote; this repairs it.
#include <vector>

#include "analysis/mesh/side_partners.hpp"
#include "core/triangle_mesh.hpp"

namespace cadnurbs {

// What orient_faces found and did (edge counts after the duplicates are dropped).
struct OrientReport {
  int components = 0;                 // sets of triangles joined across edges with exactly two faces
  int closed_components = 0;          // components none of whose edges is a boundary or non-manifold edge
  int flipped_triangles = 0;          // triangles whose corner order was reversed
  int non_orientable_components = 0;  // components with no consistent orientation (Moebius-like)
  int inconsistent_edges = 0;         // two-face edges left running the same way (only in those components)
  int duplicate_triangles = 0;        // dropped: the same three vertices as an earlier triangle, either winding
  int non_manifold_edges = 0;         // three or more faces
  int boundary_edges = 0;             // one face
};

// Takes a welded mesh (shared vertex indices; see weld_vertices), by value so that a caller done with it
// can std::move it in; returns it with
// - every triangle with the same three vertices as an earlier one (in either winding) dropped; the others
//   keep their order;
// - within each component (triangles joined across edges that have exactly two faces; a non-manifold edge
//   joins nothing) the winding of the component's first triangle kept and spread across those edges: a
//   triangle reached with the opposite winding is flipped (corners k = 0, 1, 2 become 0, 2, 1, and its
//   corner normals the same: reordered, not negated, since a file's facet normal usually points the right
//   way when its winding is wrong). In a non-orientable component each triangle keeps the winding it is
//   first reached with and the edges that then disagree are counted;
// - each closed, orientable component turned outward: flipped whole when its signed volume (sum of the
//   tetrahedra from one of its vertices) is negative. Open components keep their first triangle's winding.
// Positions are unchanged. O(n) for n triangles (plus the small sorts of side_partners). The duplicate test,
// the side partners and the flood are shared out to worker_threads() threads (vertex and triangle ranges);
// the result does not depend on the thread count (a mesh with a non-orientable component is flooded again
// in one thread, since its flips depend on the order it is walked in).
// If component_of_triangle is given it receives each output triangle's component (0 .. components - 1,
// numbered in order of their first triangles).
// If partners_of_output is given it receives side_partners() of the returned mesh (for crease_normals, which
// then need not group the edges again).
// Refuses nothing a validate()d mesh can hold; validate()s the mesh (GeometryError).
TriangleMesh orient_faces(TriangleMesh welded, OrientReport* report = nullptr,
                          std::vector<int>* component_of_triangle = nullptr,
                          SidePartners* partners_of_output = nullptr);

}  // namespace cadnurbs
