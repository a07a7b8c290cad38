#pragma once
// Trimmed NURBS tessellation with a guaranteed maximum deviation D: every point of the mesh lies
// within D of the exact (trimmed) surface and every point of the surface within D of the mesh.
//
// Method (a grid from estimates, then refinement with a certified bound). Each step is a file of
// analysis/tessellation/ (internal headers; tessellate_to_deviation.cpp runs them in this order):
//  1. grid_planning: the (u,v) domain gets a tensor grid. Each Bezier patch (distinct knot values)
//     wants n_u x n_v cells, n chosen from second derivatives sampled in the patch so that the
//     Filip-Magedson-Markot estimate (1/8)(h_u^2 M_uu + 2 h_u h_v M_uv + h_v^2 M_vv) is 0.85 D; n may be
//     a fraction (a patch already within the target shares a cell with its neighbours). The wanted
//     cells per span (the most any patch of that column or row wants) are spread evenly between C0 knot
//     lines, so smooth knots need no grid line of their own. The budget is split evenly between the two
//     directions unless one needs a single step (a cylinder's straight direction: long thin triangles,
//     which a deviation bound allows).
//  2. shared_edges: trimming loops are sampled by the deviation of their 3D image (sample_trim_segment).
//     Segments on one edge of the model (TrimEdgeRef; an untrimmed face's seam) are one model curve
//     (model_curves), curve ends that meet are one model vertex (vertex_classes, model_nodes). A curve is
//     sampled once, on its first face; the other faces find the (u,v) of the same 3D points by point
//     inversion (shared_sample_inversion: Newton on the curve on their surface from the
//     arc-length-proportional parameter, then on the surface) and use those 3D points as they are, so
//     that shared edges carry bit-identical vertices. Each chord must then also pass
//     sample_trim_segment's surface criterion and grid rule on every face that uses it, and no two
//     chords of a face may cross (loop_chord_checks); where they do not, the span is split on the curve
//     (for all its faces), so boundary triangles can be certified on every side.
//  3. face_meshing: grid points inside the loops (even-odd) and not too close to them, plus the loop
//     points, go into a constrained Delaunay triangulation of the domain (CGAL), scaled so grid cells
//     are square.
//  4. triangle_certification, with the refinement in face_meshing: every triangle is certified. Its
//     deviation (distance of the surface over its (u,v) triangle from its plane, the chordal deviation
//     of FMM and of OCCT's deflection) is at most the largest sampled distance over a lattice of
//     (k+1)(k+2)/2 points (k = 3, 6, 12, finer only while undecided) plus the rigorous bound of
//     surface_deviation_bound for one lattice sub-triangle, i.e. 1/k^2 of the whole triangle's bound:
//     n.(S - A) is a C2 function whose second derivatives are bounded by M, and its linear
//     interpolation on the lattice is bounded by the samples. (Distances to the plane, not to the
//     triangle: a surface point may lie over the neighbouring triangle, which is no deviation; the tests
//     measure the true two-sided distance.) When the bound of the whole triangle is already <= D the
//     lattice is skipped. A triangle crossing a C0 knot line is cut there first (the bound needs C1).
//     Failing triangles are refined: the midpoint of the edge where the error peaks, or the lattice
//     point where it peaks, is inserted (Delaunay). This is what guarantees the trimmed triangles, not
//     only the grid.
//  5. face_meshing: points go to 3D with per-corner normals from the surface (stepping off poles).
//  6. (on request) face_area_check: each face's mesh area against its exact area, which the deviation
//     certificate cannot see (a fold, or long triangles tilted across a twisted surface).
// Degenerate trim segments (poles: the surface point does not move along them) are one mesh
// vertex; triangles with two corners there have no area and are dropped (no slivers, no cracks).
// The trimmed strip between a (u,v) chord of a loop and the curve itself is covered by the 3D
// criterion of the loop sampling (see sample_trim_segment.hpp).
#include <string>

#include "core/scene.hpp"

namespace cadnurbs {

struct TessellationReport {
  int faces = 0;
  long triangles = 0;
  double certified_deviation = 0;    // largest certified bound over all triangles
  long uncertified_triangles = 0;    // triangles left above D (a shared edge that is too far off on
                                     // this face, or refinement stopped at 1e-9 of the domain)
  int unshared_edge_uses = 0;        // uses of a shared edge that did not match it within D (sampled
                                     // on their own: the mesh may have a crack there)
  int loops_without_area = 0;  // loops that bound no area as sampled at D (slivers thinner than D): not
                                // meshed, like the repair's loops of no area; a face of only such loops
                                // has no triangles
  int faces_beyond_area_allowance = 0;  // with check_face_areas: faces whose mesh area differs from their
                                        // area by more than face_area_check allows (their triangles are
                                        // counted as uncertified too)
};

// Triangles (counter-clockwise seen along Su x Sv) with per-corner normals, in the surface's own
// coordinates, within max_deviation of the trimmed surface. An untrimmed surface's closed sides
// (seams) and collapsed sides (poles) share their vertices. Throws GeometryError (entity "surface")
// for an invalid surface or trims, or when the triangulation fails; refuses max_deviation <= 0.
TriangleMesh tessellate_to_deviation(const TrimmedSurface& surface, double max_deviation,
                                     TessellationReport* report = nullptr);

// What tessellate_to_deviation(scene, max_deviation) reports as unshared_edge_uses, from its steps 1 and 2
// alone (no face is meshed: a small part of the cost where faces refine long). Throws what those steps
// throw; a face that step 3 would refuse is not seen.
int unshared_edge_uses(const Scene& scene, double max_deviation);

// The scene with every NURBS surface replaced by its mesh (one Shape per face: names, colours,
// transforms and tree kept; meshes and curves pass through). Segments with the same edge id carry
// bit-identical vertices on all the faces that use them, so weld_exact of a closed solid's faces
// leaves no boundary edge. A face that cannot be tessellated throws GeometryError naming its node
// path and shape. check_face_areas: step 6, every face's mesh area against its exact area
// (analysis/measure/face_area_check; costs about as much again as the meshing), so that a mesh covering part of
// a face twice, which the deviation certificate cannot see, is reported like uncertified triangles.
Scene tessellate_to_deviation(const Scene& scene, double max_deviation, TessellationReport* report = nullptr,
                              bool check_face_areas = false);

}  // namespace cadnurbs
