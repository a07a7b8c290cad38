#include "analysis/subdivision/control_mesh_edges.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace cadnurbs {

ControlMeshTopology control_mesh_topology(const SubdivisionControlMesh& mesh) {
  return {static_cast<int>(mesh.positions.size()), mesh.triangles, mesh.crease_edges, mesh.corner_vertices};
}

ControlMeshEdges control_mesh_edges(const ControlMeshTopology& level) {
  const long n = level.vertex_count;
  // Every triangle side as (key, side); sorting groups the sides of one edge without a hash map.
  struct Side {
    long key;
    int triangle, corner;
  };
  std::vector<Side> sides;
  sides.reserve(level.triangles.size() * 3);
  for (size_t t = 0; t < level.triangles.size(); ++t) {
    const auto& tri = level.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const int a = tri[k], b = tri[(k + 1) % 3];
      if (a < 0 || a >= n || b < 0 || b >= n)
        throw std::invalid_argument("control_mesh_edges: triangle " + std::to_string(t) + " has a vertex out of range");
      if (a == b) throw std::invalid_argument("control_mesh_edges: triangle " + std::to_string(t) + " repeats a vertex");
      sides.push_back({std::min(a, b) * n + std::max(a, b), static_cast<int>(t), k});
    }
  }
  std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) {
    return x.key != y.key ? x.key < y.key : x.triangle != y.triangle ? x.triangle < y.triangle : x.corner < y.corner;
  });

  ControlMeshEdges out;
  out.triangle_edges.assign(level.triangles.size(), {-1, -1, -1});
  // Edge ids in order of first appearance: number the groups by their first side's triangle.
  std::vector<std::pair<long, size_t>> groups;  // (first triangle * 3 + corner, group start)
  for (size_t i = 0; i < sides.size();) {
    size_t j = i;
    while (j < sides.size() && sides[j].key == sides[i].key) ++j;
    groups.push_back({sides[i].triangle * 3L + sides[i].corner, i});
    i = j;
  }
  std::sort(groups.begin(), groups.end());
  const size_t edge_count = groups.size();
  out.ends.resize(edge_count);
  out.opposite.assign(edge_count, {-1, -1});
  out.face_count.assign(edge_count, 0);
  out.sharp.assign(edge_count, 0);
  std::vector<long> keys(edge_count);
  for (size_t e = 0; e < edge_count; ++e) {
    const size_t start = groups[e].second;
    keys[e] = sides[start].key;
    out.ends[e] = {static_cast<int>(keys[e] / n), static_cast<int>(keys[e] % n)};
    for (size_t i = start; i < sides.size() && sides[i].key == keys[e]; ++i) {
      const auto& tri = level.triangles[sides[i].triangle];
      out.triangle_edges[sides[i].triangle][sides[i].corner] = static_cast<int>(e);
      if (out.face_count[e] < 2) out.opposite[e][out.face_count[e]] = tri[(sides[i].corner + 2) % 3];
      ++out.face_count[e];
    }
    out.sharp[e] = out.face_count[e] != 2;
  }
  // Crease tags: find each tagged pair among the keys (sorted copy for binary search).
  std::vector<std::pair<long, int>> by_key(edge_count);
  for (size_t e = 0; e < edge_count; ++e) by_key[e] = {keys[e], static_cast<int>(e)};
  std::sort(by_key.begin(), by_key.end());
  for (const auto& c : level.crease_edges) {
    const int a = std::min(c[0], c[1]), b = std::max(c[0], c[1]);
    const long key = a * n + b;
    const auto it = std::lower_bound(by_key.begin(), by_key.end(), std::make_pair(key, -1));
    if (a < 0 || b >= n || it == by_key.end() || it->first != key)
      throw std::invalid_argument("control_mesh_edges: crease tag " + std::to_string(c[0]) + "-" + std::to_string(c[1]) +
                                  " is not an edge of the mesh");
    out.sharp[it->second] = 1;
  }

  out.vertex_edges.assign(n, {});
  std::vector<int> sharp_count(n, 0);
  for (size_t e = 0; e < edge_count; ++e)
    for (const int v : out.ends[e]) {
      out.vertex_edges[v].push_back(static_cast<int>(e));
      sharp_count[v] += out.sharp[e];
    }
  out.vertex_kind.assign(n, ControlVertexKind::smooth);
  for (long v = 0; v < n; ++v) {
    const int s = sharp_count[v];
    out.vertex_kind[v] = out.vertex_edges[v].empty() ? ControlVertexKind::corner
                         : s == 0                    ? ControlVertexKind::smooth
                         : s == 1                    ? ControlVertexKind::dart
                         : s == 2                    ? ControlVertexKind::crease
                                                     : ControlVertexKind::corner;
  }
  for (const int v : level.corner_vertices) {
    if (v < 0 || v >= n) throw std::invalid_argument("control_mesh_edges: corner tag " + std::to_string(v) + " out of range");
    out.vertex_kind[v] = ControlVertexKind::corner;
  }
  return out;
}

}  // namespace cadnurbs
