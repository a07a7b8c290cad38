#pragma once
// Welding by exact position: vertices with bit-identical coordinates become one. Meant for meshes
// whose shared points were made identical on purpose (tessellate_to_deviation's shared edges), so no
// tolerance is needed or wanted: a tolerance would also merge points that are merely close.
#include "core/triangle_mesh.hpp"

namespace cadnurbs {

// The mesh with equal positions merged (first occurrence kept, order otherwise kept) and triangles
// that collapse (two corners merged) dropped; corner normals follow their triangles.
TriangleMesh weld_exact(const TriangleMesh& mesh);

}  // namespace cadnurbs
