#include "analysis/mesh/oriented_triangle_keys.hpp"

#include <algorithm>

namespace cadnurbs {

std::vector<TriangleKey> oriented_triangle_keys(const std::vector<Eigen::Vector3d>& positions,
                                                const std::vector<std::array<int, 3>>& triangles) {
  auto less = [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  };
  std::vector<TriangleKey> keys;
  keys.reserve(triangles.size());
  for (const auto& t : triangles) {
    int first = 0;
    for (int k = 1; k < 3; ++k)
      if (less(positions[t[k]], positions[t[first]])) first = k;
    TriangleKey key{};
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c) key[3 * k + c] = positions[t[(first + k) % 3]][c];
    keys.push_back(key);
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}

}  // namespace cadnurbs
