#include "analysis/subdivision_fit/tag_sharp_edges.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "analysis/subdivision_fit/turn_angle.hpp"

namespace cadnurbs {

SubdivisionControlMesh tag_sharp_edges(const TriangleMesh& mesh, double sharp_angle) {
  const int n = static_cast<int>(mesh.positions.size());
  for (const auto& t : mesh.triangles)
    for (const int v : t)
      if (v < 0 || v >= n) throw std::invalid_argument("tag_sharp_edges: vertex index " + std::to_string(v) + " is out of range");
  SubdivisionControlMesh out{mesh.positions, mesh.triangles, {}, {}};

  std::vector<Eigen::Vector3d> normal;
  normal.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d c = (mesh.positions[t[1]] - mesh.positions[t[0]]).cross(mesh.positions[t[2]] - mesh.positions[t[0]]);
    normal.push_back(c.norm() > 0 ? Eigen::Vector3d(c.normalized()) : Eigen::Vector3d::Zero());
  }
  // Every triangle side keyed by its vertex pair; equal keys are one edge's faces.
  std::vector<std::pair<std::array<int, 2>, int>> sides;
  sides.reserve(3 * mesh.triangles.size());
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      sides.push_back({{std::min(a, b), std::max(a, b)}, t});
    }
  std::sort(sides.begin(), sides.end());

  std::vector<std::vector<int>> sharp_ends(n);  // per vertex, the other ends of its sharp edges
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i;
    while (j < sides.size() && sides[j].first == sides[i].first) ++j;
    const auto [a, b] = sides[i].first;
    bool sharp = j - i != 2;  // boundary or non-manifold: sharp by Loop's rules, no tag needed
    if (!sharp) {
      const Eigen::Vector3d& n0 = normal[sides[i].second];
      const Eigen::Vector3d& n1 = normal[sides[i + 1].second];
      const bool measurable = n0.squaredNorm() > 0 && n1.squaredNorm() > 0;
      sharp = measurable && std::acos(std::clamp(n0.dot(n1), -1.0, 1.0)) >= sharp_angle;
      if (sharp) out.crease_edges.push_back({a, b});
    }
    if (sharp) {
      sharp_ends[a].push_back(b);
      sharp_ends[b].push_back(a);
    }
    i = j;
  }
  for (int v = 0; v < n; ++v) {
    if (sharp_ends[v].size() != 2) continue;
    if (turn_angle(mesh.positions[sharp_ends[v][0]], mesh.positions[v], mesh.positions[sharp_ends[v][1]]) >= sharp_angle)
      out.corner_vertices.push_back(v);
  }
  return out;
}

}  // namespace cadnurbs
