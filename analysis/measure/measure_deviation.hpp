#pragma once
// Two-sided distance between a triangle mesh and trimmed NURBS surfaces, by dense sampling:
//  mesh -> surface: points on every triangle (corners, edge and interior lattice points, the lattice
//    as fine as `spacing`), each projected on the exact surface by point inversion (Newton) started
//    from the nearest point of a fine reference triangulation of the trimmed surfaces (CGAL AABB
//    tree), and also on each side of a crease (C0 knot line) that reference triangle crosses, whose
//    interpolated (u,v) may lie on the wrong side of it. A projection that leaves the trimmed region
//    (even-odd on densely sampled loops) is replaced by the nearest point of the boundary curves
//    (Newton on the curve on the surface).
//  surface -> mesh: points of the trimmed surfaces (a grid inside the loops at `spacing`, and the
//    loops themselves) to the nearest point of the mesh (CGAL AABB tree of its triangles).
// Sampling measures, it does not bound: the maxima are attained values, never above the truth by
// more than the Newton tolerance, possibly below it between samples. Runs on all hardware threads.
#include "core/scene.hpp"

namespace cadnurbs {

struct DeviationStats {
  double max = 0;
  double rms = 0;
  long samples = 0;
};

struct DeviationMeasure {
  DeviationStats mesh_to_surface, surface_to_mesh, overall;
};

struct DeviationOptions {
  double spacing = 0;  // 3D distance between samples; 0: a third of the mesh's mean edge length
};

// `mesh` against one trimmed surface, both in the same coordinates. Refuses (GeometryError) an
// invalid surface or an empty mesh.
DeviationMeasure measure_deviation(const TriangleMesh& mesh, const TrimmedSurface& surface,
                                   const DeviationOptions& options = {});

// `mesh` (world coordinates, e.g. scene_triangles of a tessellation) against every trimmed surface
// of `scene` (placed by their world transforms).
DeviationMeasure measure_deviation(const TriangleMesh& mesh, const Scene& scene, const DeviationOptions& options = {});

// Face by face, never across faces: `mesh` is the tessellation `meshes` of `faces` (one mesh shape per
// shape of `faces`, in the same order, as tessellate_to_deviation gives it) as a file gave it back, in
// world coordinates and in the order scene_triangles(meshes) has its triangles. The triangles of each
// face are measured against that face alone, so a point is never projected onto a neighbouring face
// (which can read a distance far beyond the face's own). Shapes of `faces` that are not trimmed surfaces
// (meshes a reader fell back to) have nothing exact to be measured against and are left out. The result:
// the largest maxima, the RMS over all samples. Throws GeometryError (entity "measure") when `mesh`
// does not have the triangles of `meshes` or the two scenes do not have the same shapes.
DeviationMeasure measure_deviation_by_face(const TriangleMesh& mesh, const Scene& meshes, const Scene& faces,
                                           const DeviationOptions& options = {});

}  // namespace cadnurbs
