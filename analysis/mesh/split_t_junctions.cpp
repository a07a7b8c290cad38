#include "analysis/mesh/split_t_junctions.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "analysis/mesh/point_hash_grid.hpp"

namespace cadnurbs {

namespace {

// Boundary edges (used by one triangle, in either direction), as (triangle, corner k: edge k -> k+1).
std::vector<std::pair<int, int>> boundary_edges(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++uses[std::minmax(t[k], t[(k + 1) % 3])];
  std::vector<std::pair<int, int>> edges;
  for (size_t i = 0; i < mesh.triangles.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (uses[std::minmax(mesh.triangles[i][k], mesh.triangles[i][(k + 1) % 3])] == 1)
        edges.emplace_back(static_cast<int>(i), k);
  return edges;
}

}  // namespace

TriangleMesh split_t_junctions(const TriangleMesh& mesh, double tolerance, long* splits) {
  if (splits) *splits = 0;
  const auto edges = boundary_edges(mesh);
  std::set<int> boundary_vertices;
  for (const auto& [t, k] : edges) {
    boundary_vertices.insert(mesh.triangles[t][k]);
    boundary_vertices.insert(mesh.triangles[t][(k + 1) % 3]);
  }
  // Vertices hashed at the longest boundary edge's length: each edge's vertices lie within that of its
  // midpoint.
  double longest = 0;
  for (const auto& [t, k] : edges)
    longest = std::max(longest,
                       (mesh.positions[mesh.triangles[t][k]] - mesh.positions[mesh.triangles[t][(k + 1) % 3]]).norm());
  if (edges.empty() || !(longest > 0)) return mesh;
  PointHashGrid grid(longest);
  for (int v : boundary_vertices) grid.insert(mesh.positions[v], v);

  // For each triangle, per edge k, the vertices on it, by their parameter along the edge.
  std::map<int, std::array<std::vector<std::pair<double, int>>, 3>> on_edges;
  for (const auto& [t, k] : edges) {
    const int a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
    const Eigen::Vector3d& pa = mesh.positions[a];
    const Eigen::Vector3d ab = mesh.positions[b] - pa;
    const double length2 = ab.squaredNorm();
    if (!(length2 > 0)) continue;
    grid.find_near(pa + 0.5 * ab, [&](int v) {
      if (v == a || v == b) return false;
      const double s = (mesh.positions[v] - pa).dot(ab) / length2;
      if (s <= 0 || s >= 1) return false;
      if ((pa + s * ab - mesh.positions[v]).norm() <= tolerance) on_edges[t][k].emplace_back(s, v);
      return false;
    });
  }
  if (on_edges.empty()) return mesh;

  TriangleMesh out;
  out.positions = mesh.positions;
  for (size_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto found = on_edges.find(static_cast<int>(i));
    if (found == on_edges.end()) {
      out.triangles.push_back(mesh.triangles[i]);
      continue;
    }
    // The triangle's boundary as a polygon with the inserted vertices. With vertices on one edge only, it
    // is fanned from the opposite corner; otherwise from a new vertex at the centroid (a fan from a
    // corner would give triangles of no area along its own edges).
    const auto& t = mesh.triangles[i];
    std::vector<int> polygon;
    int edges_split = 0, split_edge = 0;
    for (int k = 0; k < 3; ++k) {
      auto on = found->second[k];
      std::sort(on.begin(), on.end());
      if (!on.empty()) {
        ++edges_split;
        split_edge = k;
      }
      polygon.push_back(t[k]);
      for (const auto& [s, v] : on) polygon.push_back(v);
      if (splits) *splits += static_cast<long>(on.size());
    }
    const size_t n = polygon.size();
    if (edges_split == 1) {
      const int corner = t[(split_edge + 2) % 3];
      const size_t start = static_cast<size_t>(std::find(polygon.begin(), polygon.end(), corner) - polygon.begin());
      for (size_t j = 1; j + 1 < n; ++j)
        out.triangles.push_back({corner, polygon[(start + j) % n], polygon[(start + j + 1) % n]});
    } else {
      const int centre = static_cast<int>(out.positions.size());
      out.positions.push_back((mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3.0);
      for (size_t j = 0; j < n; ++j) out.triangles.push_back({centre, polygon[j], polygon[(j + 1) % n]});
    }
  }
  return out;
}

}  // namespace cadnurbs
