#pragma once
// All the triangle meshes of a scene as one mesh in world coordinates (for measuring a tessellated
// scene against its NURBS, or writing it as one STL). Normals are rotated with their triangles.
#include "core/scene.hpp"

namespace cadnurbs {

// Every TriangleMesh and (fanned) PolygonMesh shape transformed by its node's world transform and appended; surfaces and
// curves are left out. Vertices are not welded.
TriangleMesh scene_triangles(const Scene& scene);

// How many triangles scene_triangles takes from `shape` (0 for surfaces and curves).
std::size_t shape_triangle_count(const Shape& shape);

}  // namespace cadnurbs
