#include "analysis/edge_sides.hpp"

#include <algorithm>
#include <cstdint>

namespace cadnurbs {

EdgeSides edge_sides(const TriangleMesh& mesh) {
  const std::size_t side_count = 3 * mesh.triangles.size();
  // Bucket the sides by their lower vertex (a counting sort, which keeps them in order of s), then sort
  // each bucket by the higher vertex: the buckets are small, and no hash of vertex pairs is needed.
  std::vector<int> start(mesh.positions.size() + 1, 0);
  for (std::size_t s = 0; s < side_count; ++s) {
    const int s_ = static_cast<int>(s);
    ++start[std::min(side_from(mesh, s_), side_to(mesh, s_)) + 1];
  }
  for (std::size_t v = 1; v < start.size(); ++v) start[v] += start[v - 1];
  EdgeSides out;
  out.sides.resize(side_count);
  {
    std::vector<int> next(start.begin(), start.end() - 1);
    for (std::size_t s = 0; s < side_count; ++s) {
      const int s_ = static_cast<int>(s);
      out.sides[next[std::min(side_from(mesh, s_), side_to(mesh, s_))]++] = s_;
    }
  }
  out.first.reserve(side_count / 2 + 1);
  std::vector<std::uint64_t> keyed;  // (higher vertex, side) of one bucket
  for (std::size_t v = 0; v + 1 < start.size(); ++v) {
    const int begin = start[v], end = start[v + 1];
    keyed.clear();
    for (int i = begin; i < end; ++i) {
      const int s = out.sides[i];
      const auto high = static_cast<std::uint32_t>(std::max(side_from(mesh, s), side_to(mesh, s)));
      keyed.push_back(std::uint64_t{high} << 32 | static_cast<std::uint32_t>(s));
    }
    std::sort(keyed.begin(), keyed.end());
    for (int i = begin; i < end; ++i) {
      const std::uint64_t key = keyed[i - begin];
      if (i == begin || key >> 32 != keyed[i - begin - 1] >> 32) out.first.push_back(i);
      out.sides[i] = static_cast<int>(key & 0xffffffffu);
    }
  }
  out.first.push_back(static_cast<int>(side_count));
  return out;
}

}  // namespace cadnurbs
