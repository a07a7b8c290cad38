#pragma once
// A Scene as an XCAF document for OCCT's STEP and IGES writers. Internal to formats/brep, step and iges:
// includes OCCT.
#include <TDocStd_Document.hxx>

#include "core/scene.hpp"

namespace cadnurbs {

// Takes a valid scene (any length unit: coordinates are converted to millimetres). Returns a document in
// millimetres where:
// - a node without children is a part; a node with children an assembly of its children (each placed by
//   its transform, which must be a rigid motion, possibly scaled) and, when it has shapes, of a part named
//   after it holding them;
// - a part's trimmed surfaces become faces (trimmed_surface_to_face), its meshes triangular planar faces,
//   its 3D curves edges; the faces are sewn (BRepBuilderAPI_Sewing, tolerance 1e-6 x the scene's bounding
//   box diagonal, at least 1e-6 mm) and every shell that closes becomes a solid oriented outward;
// - names from the nodes and, when `face_names`, the shapes; colours from the nodes (part colour) and shapes
//   (face colour).
// Throws GeometryError for geometry OCCT refuses (naming node and shape).
Handle(TDocStd_Document) scene_to_xcaf(const Scene& scene, bool face_names = true);

}  // namespace cadnurbs
