#include "core/triangle_mesh.hpp"

#include "core/geometry_error.hpp"

namespace cadnurbs {

void validate(const TriangleMesh& mesh, const std::string& entity) {
  const int n = static_cast<int>(mesh.positions.size());
  for (size_t i = 0; i < mesh.positions.size(); ++i)
    if (!mesh.positions[i].allFinite()) throw GeometryError(entity, "vertex " + std::to_string(i) + " is not finite");
  for (size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k : mesh.triangles[t])
      if (k < 0 || k >= n)
        throw GeometryError(entity, "triangle " + std::to_string(t) + " uses vertex " + std::to_string(k) + " of " +
                                        std::to_string(n));
  if (!mesh.corner_normals.empty() && mesh.corner_normals.size() != 3 * mesh.triangles.size())
    throw GeometryError(entity, std::to_string(mesh.corner_normals.size()) + " corner normals for " +
                                    std::to_string(mesh.triangles.size()) + " triangles");
}

double mesh_area(const TriangleMesh& mesh) {
  double area = 0.0;
  for (const auto& t : mesh.triangles)
    area += 0.5 * (mesh.positions[t[1]] - mesh.positions[t[0]]).cross(mesh.positions[t[2]] - mesh.positions[t[0]]).norm();
  return area;
}

void append(TriangleMesh& mesh, const TriangleMesh& other) {
  const int offset = static_cast<int>(mesh.positions.size());
  const bool normals = !mesh.corner_normals.empty() || mesh.triangles.empty();
  mesh.positions.insert(mesh.positions.end(), other.positions.begin(), other.positions.end());
  for (const auto& t : other.triangles) mesh.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  if (normals && other.corner_normals.size() == 3 * other.triangles.size())
    mesh.corner_normals.insert(mesh.corner_normals.end(), other.corner_normals.begin(), other.corner_normals.end());
  else
    mesh.corner_normals.clear();
}

}  // namespace cadnurbs
