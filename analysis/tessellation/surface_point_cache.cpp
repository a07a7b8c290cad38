#include "analysis/tessellation/surface_point_cache.hpp"

#include <algorithm>
#include <bit>

#include "core/bit_cast.hpp"

namespace cadnurbs::tessellation {

namespace {

// 8192 slots of 48 bytes: within a second-level cache.
constexpr std::size_t kMaxSlots = 8192;

std::size_t slot_of(std::uint64_t u, std::uint64_t v, std::size_t mask) {
  // splitmix64's finaliser over both keys: nearby parameters differ in their low mantissa bits only.
  std::uint64_t h = u * 0x9E3779B97F4A7C15ull ^ (v + 0x632BE59BD9B4E019ull);
  h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
  h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
  return static_cast<std::size_t>(h ^ (h >> 31)) & mask;
}

}  // namespace

SurfacePointCache::SurfacePointCache(const SurfaceEvaluator& surface, std::size_t expected)
    : surface_(surface), slots_(std::min(kMaxSlots, std::bit_ceil(std::max<std::size_t>(64, 2 * expected)))) {}

Eigen::Vector3d SurfacePointCache::point(double u, double v) {
  const auto ku = bit_cast<std::uint64_t>(u), kv = bit_cast<std::uint64_t>(v);
  Slot& slot = slots_[slot_of(ku, kv, slots_.size() - 1)];
  if (slot.used && slot.u == ku && slot.v == kv) return slot.point;
  slot = {ku, kv, surface_.point(u, v), true};
  return slot.point;
}

}  // namespace cadnurbs::tessellation
