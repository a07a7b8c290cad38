#include "core/polygon_mesh.hpp"

#include "core/geometry_error.hpp"

namespace cadnurbs {

void validate(const PolygonMesh& mesh, const std::string& entity) {
  const int n = static_cast<int>(mesh.positions.size());
  for (size_t i = 0; i < mesh.positions.size(); ++i)
    if (!mesh.positions[i].allFinite()) throw GeometryError(entity, "vertex " + std::to_string(i) + " is not finite");
  for (size_t f = 0; f < mesh.polygons.size(); ++f) {
    if (mesh.polygons[f].size() < 3)
      throw GeometryError(entity, "polygon " + std::to_string(f) + " has " + std::to_string(mesh.polygons[f].size()) +
                                      " corners");
    for (int k : mesh.polygons[f])
      if (k < 0 || k >= n)
        throw GeometryError(entity, "polygon " + std::to_string(f) + " uses vertex " + std::to_string(k) + " of " +
                                        std::to_string(n));
  }
}

TriangleMesh triangulated(const PolygonMesh& mesh) {
  TriangleMesh out;
  out.positions = mesh.positions;
  for (const auto& polygon : mesh.polygons)
    for (size_t k = 1; k + 1 < polygon.size(); ++k) out.triangles.push_back({polygon[0], polygon[k], polygon[k + 1]});
  return out;
}

std::size_t triangulated_count(const PolygonMesh& mesh) {
  std::size_t count = 0;
  for (const auto& polygon : mesh.polygons) count += polygon.size() > 2 ? polygon.size() - 2 : 0;
  return count;
}

}  // namespace cadnurbs
