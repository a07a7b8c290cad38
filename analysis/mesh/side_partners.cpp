#include "analysis/mesh/side_partners.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>

#include "analysis/mesh/vertex_buckets.hpp"
#include "core/worker_threads.hpp"

namespace cadnurbs {

SidePartners side_partners(const TriangleMesh& mesh) {
  SidePartners out;
  out.partner.assign(3 * mesh.triangles.size(), -1);
  const auto& T = mesh.triangles;
  std::vector<SidePartners> counts(worker_threads());
  // Each side in its lower vertex's bucket, as (higher vertex, side); a bucket sorted by the higher vertex
  // holds the vertex's edges one after the other.
  auto side = [&](std::size_t t, int k) {
    const int from = T[t][k], to = T[t][(k + 1) % 3];
    return BucketEntry{static_cast<std::size_t>(std::min(from, to)),
                       std::uint64_t{static_cast<std::uint32_t>(std::max(from, to))} << 32 | (3 * t + k)};
  };
  visit_vertex_buckets(mesh.positions.size(), T.size(), 3, side, [&](int w, std::uint64_t* begin, std::uint64_t* end) {
    for (std::uint64_t* i = begin + 1; i < end; ++i)  // insertion sort: a few sides, nearly in order
      for (std::uint64_t* j = i; j > begin && j[-1] > j[0]; --j) std::swap(j[-1], j[0]);
    for (std::uint64_t* i = begin; i < end;) {
      std::uint64_t* edge_end = i + 1;
      while (edge_end < end && *edge_end >> 32 == *i >> 32) ++edge_end;
      if (edge_end - i == 2) {
        const int s1 = static_cast<int>(i[0] & 0xffffffffu), s2 = static_cast<int>(i[1] & 0xffffffffu);
        out.partner[s1] = s2;
        out.partner[s2] = s1;
      } else {
        ++(edge_end - i == 1 ? counts[w].boundary_edges : counts[w].non_manifold_edges);
      }
      i = edge_end;
    }
  });
  for (const SidePartners& c : counts) {
    out.boundary_edges += c.boundary_edges;
    out.non_manifold_edges += c.non_manifold_edges;
  }
  return out;
}

}  // namespace cadnurbs
