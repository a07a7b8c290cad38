#pragma once
// How a read scene is made ready for a writer, shared by convert and report so that the report measures
// exactly what convert writes: the compact NURBS form, and the certified mesh (sewn first when the file
// named no edges).
#include "analysis/compact_scene.hpp"
#include "analysis/sew_faces.hpp"
#include "analysis/tessellate_to_deviation.hpp"
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

struct CertifiedMesh {
  Scene meshes;                 // one TriangleMesh shape per face; tree, names and colours kept
  TessellationReport report;
  bool sewn = false;            // the scene named no edges, so it was sewn first
  Scene faces;                  // what was tessellated when sewn: the sewn faces, with shared-edge ids
  SewingTolerance sewing_tolerance;
  SewingReport sewing;
};

// Every NURBS face of `scene` tessellated within `max_deviation` (tessellate_to_deviation). A scene read
// from a file that names no edges (loaded.face_count == 0: VRML/X3D, our own NURBS files) is sewn first
// (sew_faces at sewing_tolerance(diagonal, D)), so that its mesh is as watertight as the B-rep's.
CertifiedMesh certified_mesh(const BrepTranslation& loaded, const Scene& scene, double max_deviation,
                             bool check_face_areas = false);

}  // namespace cadnurbs
