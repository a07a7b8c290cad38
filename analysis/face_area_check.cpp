#include "analysis/face_area_check.hpp"

#include <algorithm>
#include <map>

#include "analysis/trimmed_surface_area.hpp"

namespace cadnurbs {

double boundary_length(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++uses[std::minmax(t[k], t[(k + 1) % 3])];
  double length = 0;
  for (const auto& [edge, n] : uses)
    if (n == 1) length += (mesh.positions[edge.first] - mesh.positions[edge.second]).norm();
  return length;
}

FaceAreaCheck check_face_area(const TrimmedSurface& face, const TriangleMesh& mesh, double max_deviation) {
  FaceAreaCheck out;
  out.area = trimmed_surface_area(face, 1e-7);
  out.mesh_area = mesh_area(mesh);
  const double relative = out.area < 1 ? 0.005 : 0.001;
  out.allowance = std::max(relative * out.area, max_deviation * boundary_length(mesh));
  return out;
}

}  // namespace cadnurbs
