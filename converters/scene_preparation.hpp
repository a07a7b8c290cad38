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
