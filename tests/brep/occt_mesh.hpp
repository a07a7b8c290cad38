#pragma once
// OCCT's own tessellation of a shape, as the peer our tessellation is compared with (tests and bench).
#include <TopoDS_Shape.hxx>

#include "core/triangle_mesh.hpp"

namespace cadnurbs::test {

// Runs BRepMesh_IncrementalMesh on `shape` (absolute deflection, angular deflection 1.5 rad so that
// only the deflection decides, single-threaded).
void occt_mesh(const TopoDS_Shape& shape, double deflection);

// The triangulations stored on the faces of `shape`, in world coordinates, triangles turned for
// reversed faces (outward); faces without one are skipped.
TriangleMesh occt_triangles(const TopoDS_Shape& shape);

}  // namespace cadnurbs::test
