#pragma once
// The mesh a face is written as when it cannot be a trimmed NURBS. Internal to formats/brep: includes OCCT.
#include <TopoDS_Face.hxx>

#include "core/triangle_mesh.hpp"

namespace cadnurbs {

// Takes a face (oriented as its shell uses it) and a deflection in model units. Returns BRepMesh's
// triangulation of it (BRepMesh_IncrementalMesh; an existing finer one is reused), triangles
// counter-clockwise seen from outside the material, per-corner normals from the surface (the facet normal
// where the surface has none). Empty when OCCT cannot mesh the face.
// Refuses (std::domain_error, "not meshed either: <reason>") a face that why_not_meshable
// (face_mesh_guard.hpp) turns away, on which BRepMesh could loop without end.
TriangleMesh face_mesh(const TopoDS_Face& face, double deflection);

}  // namespace cadnurbs
