#include "analysis/mesh/weld_exact.hpp"

#include <map>

namespace cadnurbs {

TriangleMesh weld_exact(const TriangleMesh& mesh) {
  // Lexicographic order on the coordinates: exact equality, and -0.0 == 0.0 as it should be.
  auto less = [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    if (a.x() != b.x()) return a.x() < b.x();
    if (a.y() != b.y()) return a.y() < b.y();
    return a.z() < b.z();
  };
  std::map<Eigen::Vector3d, int, decltype(less)> index(less);
  TriangleMesh out;
  std::vector<int> remap(mesh.positions.size());
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const auto [it, fresh] = index.emplace(mesh.positions[i], static_cast<int>(out.positions.size()));
    if (fresh) out.positions.push_back(mesh.positions[i]);
    remap[i] = it->second;
  }
  const bool normals = mesh.corner_normals.size() == 3 * mesh.triangles.size();
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const std::array<int, 3> m{remap[mesh.triangles[t][0]], remap[mesh.triangles[t][1]], remap[mesh.triangles[t][2]]};
    if (m[0] == m[1] || m[1] == m[2] || m[2] == m[0]) continue;
    out.triangles.push_back(m);
    if (normals)
      for (int k = 0; k < 3; ++k) out.corner_normals.push_back(mesh.corner_normals[3 * t + k]);
  }
  return out;
}

}  // namespace cadnurbs
