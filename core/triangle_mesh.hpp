#pragma once
// An indexed triangle mesh with optional per-corner normals.
#include <Eigen/Geometry>
#include <array>
#include <string>
#include <vector>

namespace cadnurbs {

struct TriangleMesh {
  std::vector<Eigen::Vector3d> positions;
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise seen from outside
  std::vector<Eigen::Vector3d> corner_normals;  // empty, or 3 per triangle (corner k of triangle t at 3t+k)
};

// Throws GeometryError unless every index is in range, positions are finite, and normals are
// empty or three per triangle.
void validate(const TriangleMesh& mesh, const std::string& entity);

// Total area of the triangles.
double mesh_area(const TriangleMesh& mesh);

// Appends `other` to `mesh`, offsetting indices.
void append(TriangleMesh& mesh, const TriangleMesh& other);

}  // namespace cadnurbs
