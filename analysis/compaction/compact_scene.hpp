#pragma once
// The exact rewrites that make a scene small to write as VRML/X3D, each moving no point by more than the
// written precision τ (the coordinate tolerance the writer keeps):
//   - parts repeated up to a rigid motion become copies of one part placed by transforms
//     (instance_repeated_parts, within τ/4), which the writer writes once; then single curved faces
//     (instance_repeated_faces: holes, fillets);
//   - planar faces bounded by straight edges become exact polygons (planar_face_polygons), all those of
//     one node and colour one PolygonMesh with welded vertices (weld_polygon_meshes, within τ/4);
//   - trimming curves lose the knots their shape does not need (knot_removal, moving them by at most τ/4
//     in 3D), then runs of straight trimming segments become polylines (join_straight_trim_runs);
//   - a trimming loop that is just the surface's own domain boundary is dropped (untrimmed surface);
//   - knot vectors become whole numbers where an affine map allows (whole_number_knots).
// What the writer does besides (one DEF/USE per repeated node) is the writer's. Faces that carry a name
// from the source keep their own shape. Curves and meshes pass through.
#include "core/scene.hpp"

namespace cadnurbs {

struct CompactReport {
  int planar_faces = 0;    // faces written as exact polygons
  int polygon_meshes = 0;  // the PolygonMesh shapes they went into
  int straight_runs = 0;   // polylines made of two or more straight trimming segments
  int untrimmed = 0;       // faces whose only loop was their domain boundary
  int reparametrised = 0;  // knot vectors mapped to whole numbers
  long knots_removed = 0;  // from trimming curves
  int instanced = 0;       // repeated parts placed as translated copies of one
};

// compact_scene's first rewrite alone, in place: repeated parts, then single curved faces that will not
// become polygons, placed as copies within τ/4 (`tolerance` = τ). Returns the copies placed. Run before
// anything that changes faces one by one (simplify_scene), so that copies stay exact copies.
int instance_repeats(SceneNode& node, double tolerance);

// `tolerance` = τ > 0, in the scene's units. Throws std::invalid_argument for τ <= 0 or not finite.
Scene compact_scene(const Scene& scene, double tolerance, CompactReport* report = nullptr);

}  // namespace cadnurbs
