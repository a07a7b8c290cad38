#include "analysis/edge_sides.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>

namespace cadnurbs {

namespace {

// Calls visit(sides, count) for each edge, edges in order of (lower vertex, higher vertex), an edge's sides
// in increasing order. The sides are bucketed by their lower vertex (a counting sort, which keeps them in
// order of s) with their higher vertex beside them, then each bucket is sorted by the higher vertex: the
// buckets are small (a vertex's sides), and no hash of vertex pairs is needed.
template <class Visit>
void visit_edges(const TriangleMesh& mesh, Visit&& visit) {
  const std::size_t side_count = 3 * mesh.triangles.size();
  std::vector<int> start(mesh.positions.size() + 1, 0);
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++start[std::min(t[k], t[(k + 1) % 3]) + 1];
  for (std::size_t v = 1; v < start.size(); ++v) start[v] += start[v - 1];
  std::vector<std::uint64_t> keyed(side_count);  // (higher vertex, side), bucketed by the lower vertex
  {
    std::vector<int> next(start.begin(), start.end() - 1);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        const int from = mesh.triangles[t][k], to = mesh.triangles[t][(k + 1) % 3];
        keyed[next[std::min(from, to)]++] = std::uint64_t{static_cast<std::uint32_t>(std::max(from, to))} << 32 | (3 * t + k);
      }
  }
  std::vector<int> sides;
  for (std::size_t v = 0; v + 1 < start.size(); ++v) {
    std::uint64_t* const begin = keyed.data() + start[v];
    std::uint64_t* const end = keyed.data() + start[v + 1];
    for (std::uint64_t* i = begin + 1; i < end; ++i)  // insertion sort: a few sides, nearly in order
      for (std::uint64_t* j = i; j > begin && j[-1] > j[0]; --j) std::swap(j[-1], j[0]);
    for (std::uint64_t* i = begin; i < end;) {
      sides.clear();
      const std::uint64_t higher = *i >> 32;
      for (; i < end && *i >> 32 == higher; ++i) sides.push_back(static_cast<int>(*i & 0xffffffffu));
      visit(sides.data(), static_cast<int>(sides.size()));
    }
  }
}

}  // namespace

EdgeSides edge_sides(const TriangleMesh& mesh) {
  EdgeSides out;
  out.sides.reserve(3 * mesh.triangles.size());
  out.first.reserve(3 * mesh.triangles.size() / 2 + 1);
  visit_edges(mesh, [&](const int* sides, int count) {
    out.first.push_back(static_cast<int>(out.sides.size()));
    out.sides.insert(out.sides.end(), sides, sides + count);
  });
  out.first.push_back(static_cast<int>(out.sides.size()));
  return out;
}

SidePartners side_partners(const TriangleMesh& mesh) {
  SidePartners out;
  out.partner.assign(3 * mesh.triangles.size(), -1);
  visit_edges(mesh, [&](const int* sides, int count) {
    if (count == 2) {
      out.partner[sides[0]] = sides[1];
      out.partner[sides[1]] = sides[0];
    } else {
      ++(count == 1 ? out.boundary_edges : out.non_manifold_edges);
    }
  });
  return out;
}

}  // namespace cadnurbs
