#pragma once
// How a read scene is made ready for a writer, shared by convert and report so that the report measures
// exactly what convert writes: the compact NURBS form, and the certified mesh (sewn first when the file
// named no edges).
#include "analysis/certified_mesh/certified_scene_mesh.hpp"
#include "analysis/compaction/compact_scene.hpp"
#include "analysis/mesh/count_boundary_edges.hpp"
#include "analysis/sewing/sew_faces.hpp"
#include "analysis/knots/simplify_scene.hpp"
#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "formats/brep/brep_translation.hpp"

namespace cadnurbs {

// The written precision: what compaction may move a coordinate by (model units). significant_digits 0:
// the default, 1e-6 of the bounding-box diagonal; else half a unit in the last of that many digits of
// the largest coordinate.
double written_tolerance(const Scene& scene, int significant_digits);

// The bounding-box diagonal of the scene read from `in`, once its coordinates are known to be usable:
// every placed control point and vertex finite and below kLargestCoordinate, so that the lengths,
// squared lengths and areas derived from them stay finite. Throws FileError naming `in`: "<in>: a
// coordinate is not finite once placed (a transform overflows)" or "<in>: the part's size is not finite
// in double precision (coordinates up to 1e+308; squared lengths overflow beyond 1e+150): scale it down".
double checked_diagonal(const Scene& scene, const std::string& in);
constexpr double kLargestCoordinate = 1e150;  // its square, and sums of squares, stay below DBL_MAX

// checked_diagonal of a triangle mesh read from `in` (normals, fit-loop), refusing also a mesh whose
// points all coincide: "<in>: all points coincide: every triangle is degenerate".
double checked_mesh_diagonal(const TriangleMesh& mesh, const std::string& in);

// The default maximum deviation: 1e-3 of `diagonal` (checked_diagonal). Throws FileError "<in>: all
// points coincide: give --deviation" when the diagonal is 0 and so no size can be derived from it.
double default_deviation(double diagonal, const std::string& in);

// certified_scene_mesh (analysis/certified_mesh) of a scene read as `loaded` says: sewn first only when
// no B-rep reader numbered its edges (loaded.face_count == 0: VRML/X3D, our own NURBS files).
CertifiedMesh certified_mesh(const BrepTranslation& loaded, const Scene& scene, double max_deviation,
                             bool check_face_areas = false);

// convert --simplify D: the scene with knots removed (simplify_scene) and what certifies it.
//  - Repeated parts are first placed as exact copies (instance_repeats at `written_tolerance`, as the
//    compact writer would), so that every copy loses the same knots and is still written once.
//  - Every face and 3D curve moves by at most D/8 (kSimplifyShare), so that two faces along a shared
//    edge part by at most D/4: the widest gap sewing bridges for a mesh at D (sewing_tolerance). Sewing
//    cuts a piece at a neighbour's vertex (a T-junction) only within its first tolerance, 1e-5 of the
//    diagonal, and a file's own gaps add to the parting; so when the mesh at D of the simplified scene
//    has lost watertightness (below), the move is divided by 8 and the removal redone, up to
//    kSimplifyAttempts moves (D/8, D/64, D/512); if none keeps it, the scene is returned unchanged.
//  - The deviation, face by face: every face knot removal changed, as it was, meshed within D/4
//    (tessellate_to_deviation) and measured against itself simplified (measure_deviation, two-sided, the
//    face alone); the two then lie within measured + that mesh's certified deviation of each other, and
//    the copies placed first within τ/4 more. 3D curves: sampled at equal parameters.
//  - Watertightness, before and after alike: the compact form (compact_scene at `written_tolerance`)
//    with its edge ids forgotten, as a reader of the written file finds it, sewn (sew_faces at
//    sewing_tolerance(diagonal, D)), meshed at D and welded (weld_exact); its open edges counted.
struct SimplifiedScene {
  Scene scene;
  double max_deviation = 0;        // D
  SimplifyReport knots;
  int instanced = 0;               // copies of repeated parts placed before simplifying (instance_repeats)
  int attempts = 0;                // moves tried
  double max_move = 0;             // the move allowed (D/8, D/64 or D/512); 0: the scene is unchanged
  double measured = 0;             // measure_deviation's largest over the changed faces
  double mesh_deviation = 0;       // largest certified deviation of their meshes before
  double copies_moved = 0;         // τ/4 when copies were placed, else 0
  double certified_deviation = 0;  // max(measured + mesh_deviation, knots.curve_deviation) + copies_moved
  EdgeCounts open_before, open_after;
  int unshared_before = 0, unshared_after = 0;  // edge uses the tessellator could not share
  // No edge use lost its edge and no non-manifold edge appeared; a closed mesh stayed closed, and an
  // open one's boundary grew by at most 1 % of its length plus D (a crack adds twice its length; the
  // sampling of an open boundary, and slivers far below D, may change its length a little).
  bool watertight_kept() const;
};
constexpr double kSimplifyShare = 0.125;
constexpr int kSimplifyAttempts = 3;

// Refuses (std::invalid_argument) a max_deviation that is not a positive number.
SimplifiedScene simplified_scene(const Scene& scene, double max_deviation, double written_tolerance);

}  // namespace cadnurbs
