#include "core/equal_points.hpp"

#include <bit>
#include <cstring>

#include "core/bit_cast.hpp"

namespace cadnurbs {

std::uint64_t EqualPoints::hash(const Eigen::Vector3d& p) {
  std::uint64_t h = 0;
  for (int i = 0; i < 3; ++i) {
    h = (h ^ bit_cast<std::uint64_t>(p[i])) * 0x9e3779b97f4a7c15ull;
    h ^= h >> 29;
  }
  return h;
}

int EqualPoints::add(const Eigen::Vector3d& p) {
  const auto h = static_cast<std::uint32_t>(hash(p) >> 32);
  const std::size_t mask = slots_.size() - 1;
  std::size_t i = h & mask;
  for (; slots_[i].point >= 0; i = (i + 1) & mask)
    if (slots_[i].hash == h && std::memcmp(points_[slots_[i].point].data(), p.data(), sizeof(double) * 3) == 0)
      return slots_[i].point;
  const int number = static_cast<int>(points_.size());
  slots_[i] = {h, number};
  points_.push_back(p);
  if (2 * points_.size() > slots_.size()) grow();
  return number;
}

void EqualPoints::reserve(std::size_t count) {
  points_.reserve(count);
  std::size_t size = slots_.size();
  while (size < 2 * count) size *= 2;
  if (size > slots_.size()) rehash(size);
}

void EqualPoints::grow() { rehash(2 * slots_.size()); }

void EqualPoints::rehash(std::size_t size) {
  std::vector<Slot> old(size);
  old.swap(slots_);
  const std::size_t mask = slots_.size() - 1;
  for (const Slot& slot : old) {
    if (slot.point < 0) continue;
    std::size_t i = slot.hash & mask;
    while (slots_[i].point >= 0) i = (i + 1) & mask;
    slots_[i] = slot;
  }
}

}  // namespace cadnurbs
