#include "analysis/tessellation/surface_point_cache.hpp"

#include <algorithm>
#include <bit>

namespace cadnurbs::tessellation {

namespace {

std::size_t slot_of(std::uint64_t u, std::uint64_t v, std::size_t mask) {
  // splitmix64's finaliser over both keys: nearby parameters differ in their low mantissa bits only.
  std::uint64_t h = u * 0x9E3779B97F4A7C15ull ^ (v + 0x632BE59BD9B4E019ull);
  h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
  h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
  return static_cast<std::size_t>(h ^ (h >> 31)) & mask;
}

}  // namespace

SurfacePointCache::SurfacePointCache(const SurfaceEvaluator& surface, std::size_t expected)
    : surface_(surface), slots_(std::bit_ceil(std::max<std::size_t>(64, 2 * expected)), 0) {
  entries_.reserve(expected);
}

Eigen::Vector3d SurfacePointCache::point(double u, double v) {
  const auto ku = std::bit_cast<std::uint64_t>(u), kv = std::bit_cast<std::uint64_t>(v);
  const std::size_t mask = slots_.size() - 1;
  std::size_t i = slot_of(ku, kv, mask);
  for (; slots_[i] != 0; i = (i + 1) & mask) {
    const Entry& e = entries_[slots_[i] - 1];
    if (e.u == ku && e.v == kv) return e.point;
  }
  const Eigen::Vector3d p = surface_.point(u, v);
  entries_.push_back({ku, kv, p});
  slots_[i] = static_cast<std::uint32_t>(entries_.size());
  if (2 * entries_.size() > slots_.size()) grow();
  return p;
}

void SurfacePointCache::grow() {
  slots_.assign(2 * slots_.size(), 0);
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t k = 0; k < entries_.size(); ++k) {
    std::size_t i = slot_of(entries_[k].u, entries_[k].v, mask);
    while (slots_[i] != 0) i = (i + 1) & mask;
    slots_[i] = static_cast<std::uint32_t>(k + 1);
  }
}

}  // namespace cadnurbs::tessellation
