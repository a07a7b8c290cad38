#include "analysis/mesh/count_boundary_edges.hpp"

#include <algorithm>
#include <unordered_map>

namespace cadnurbs {

EdgeCounts count_boundary_edges(const TriangleMesh& mesh) {
  std::unordered_map<std::uint64_t, int> uses;
  uses.reserve(mesh.triangles.size() * 2);
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const auto a = static_cast<std::uint32_t>(std::min(t[k], t[(k + 1) % 3]));
      const auto b = static_cast<std::uint32_t>(std::max(t[k], t[(k + 1) % 3]));
      ++uses[(static_cast<std::uint64_t>(a) << 32) | b];
    }
  EdgeCounts out;
  for (const auto& [edge, n] : uses) {
    if (n == 1) {
      ++out.boundary;
      out.boundary_length += (mesh.positions[edge >> 32] - mesh.positions[edge & 0xffffffffu]).norm();
    }
    if (n > 2) ++out.non_manifold;
  }
  return out;
}

}  // namespace cadnurbs
