#include "analysis/subdivision_fit/crease_flat_corner_spans.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

namespace cadnurbs {

SubdivisionControlMesh crease_flat_corner_spans(SubdivisionControlMesh mesh, double flat_angle) {
  if (!(flat_angle >= 0)) throw std::invalid_argument("crease_flat_corner_spans: the flatness angle must be 0 or more");
  const int n = static_cast<int>(mesh.positions.size());
  for (const auto& t : mesh.triangles)
    for (const int v : t)
      if (v < 0 || v >= n)
        throw std::invalid_argument("crease_flat_corner_spans: vertex index " + std::to_string(v) + " is out of range");

  std::map<std::array<int, 2>, std::vector<int>> faces;  // each edge's faces
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      faces[{std::min(a, b), std::max(a, b)}].push_back(t);
    }
  const std::set<std::array<int, 2>> creases(mesh.crease_edges.begin(), mesh.crease_edges.end());
  // A vertex is a corner of Loop's rules when tagged or on 3 or more sharp edges (creases, borders,
  // non-manifold edges).
  std::vector<int> sharp_edges(n, 0);
  for (const auto& [edge, at] : faces)
    if (at.size() != 2 || creases.count(edge)) {
      ++sharp_edges[edge[0]];
      ++sharp_edges[edge[1]];
    }
  std::vector<bool> corner(n, false);
  for (int v = 0; v < n; ++v) corner[v] = sharp_edges[v] >= 3;
  for (const int v : mesh.corner_vertices)
    if (v >= 0 && v < n) corner[v] = true;

  auto normal = [&](int t) {
    const auto& f = mesh.triangles[t];
    const Eigen::Vector3d c =
        (mesh.positions[f[1]] - mesh.positions[f[0]]).cross(mesh.positions[f[2]] - mesh.positions[f[0]]);
    return c.norm() > 0 ? Eigen::Vector3d(c.normalized()) : Eigen::Vector3d::Zero();
  };
  for (const auto& [edge, at] : faces) {
    if (at.size() != 2 || creases.count(edge) || !corner[edge[0]] || !corner[edge[1]]) continue;
    const Eigen::Vector3d n0 = normal(at[0]), n1 = normal(at[1]);
    if (n0.squaredNorm() == 0 || n1.squaredNorm() == 0) continue;
    if (std::acos(std::clamp(n0.dot(n1), -1.0, 1.0)) < flat_angle) mesh.crease_edges.push_back(edge);
  }
  return mesh;
}

}  // namespace cadnurbs
