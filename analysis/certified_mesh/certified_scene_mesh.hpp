#pragma once
// A whole scene's certified mesh, as `convert --mesh` writes it and the browser module draws it: every
// NURBS face tessellated within D (tessellate_to_deviation), after sewing the faces of a file that does
// not say which faces meet (sew_faces), so that the mesh is as watertight as the part.
#include "analysis/sewing/sew_faces.hpp"
#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "core/scene.hpp"

namespace cadnurbs {

// Where the scene's shared edges come from.
enum class EdgeSource {
  brep,  // a B-rep reader (STEP, IGES) numbered every edge from the solid's topology: never sewn
  file,  // a file of faces (VRML/X3D, .cnb): sewn when sewn_when_meshed says so
};

struct CertifiedMesh {
  Scene meshes;                 // one TriangleMesh shape per face; tree, names and colours kept
  TessellationReport report;
  bool sewn = false;            // the scene named no edges, so it was sewn first
  Scene faces;                  // what was tessellated when sewn: the sewn faces, with shared-edge ids
  SewingTolerance sewing_tolerance;
  SewingReport sewing;
};

// Every NURBS face of `scene` tessellated within `max_deviation`. A scene from a file of faces is sewn
// first (sew_faces at sewing_tolerance(diagonal, D)) when sewn_when_meshed(scene). check_face_areas: as
// tessellate_to_deviation's. Throws what tessellate_to_deviation throws.
CertifiedMesh certified_scene_mesh(const Scene& scene, double max_deviation, EdgeSource edges,
                                   bool check_face_areas = false);

// What certified_scene_mesh(scene, max_deviation, edges) reports as unshared_edge_uses, without meshing a
// face: sewn as it sews, then tessellate_to_deviation's steps 1 and 2 (unshared_edge_uses).
int certified_scene_unshared_edge_uses(const Scene& scene, double max_deviation, EdgeSource edges);

// Whether a scene from a file of faces is sewn before meshing: it has NURBS faces or polygon sets, and
// polygon sets, or an untrimmed face, or a loop without edge numbers, or no edge number that two faces
// share. Not when its loops carry shared-edge numbers and it holds no polygon sets (a .cnb of the exact
// NURBS): sewing at D/4 would miss what the file already says, as the quantised trims of a .cnb at D may
// lie up to D apart (as1-oc-214's .cnb at 1 mm: 236 pieces left open).
bool sewn_when_meshed(const Scene& scene);

}  // namespace cadnurbs
