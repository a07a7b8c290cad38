#pragma once
// A mesh of planar convex polygons sharing vertices: the exact form of a CAD model's planar faces that
// are bounded by straight edges (VRML/X3D IndexedFaceSet with convex TRUE). Any fan of a polygon
// covers it exactly, so readers and consumers that want triangles take triangulated().
#include <Eigen/Geometry>
#include <cstddef>
#include <string>
#include <vector>

#include "core/triangle_mesh.hpp"

namespace cadnurbs {

struct PolygonMesh {
  std::vector<Eigen::Vector3d> positions;
  std::vector<std::vector<int>> polygons;  // each convex and planar, counter-clockwise seen from outside
};

// Throws GeometryError unless every index is in range, every polygon has 3 or more corners, and positions
// are finite. (Planarity and convexity are the maker's promise; they are not checked.)
void validate(const PolygonMesh& mesh, const std::string& entity);

// The same surface as triangles: each polygon fanned from its first corner; same positions.
TriangleMesh triangulated(const PolygonMesh& mesh);

// How many triangles triangulated(mesh) makes, without making them.
std::size_t triangulated_count(const PolygonMesh& mesh);

}  // namespace cadnurbs
