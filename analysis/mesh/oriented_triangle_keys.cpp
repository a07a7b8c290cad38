#include "analysis/mesh/oriented_triangle_keys.hpp"

#include <algorithm>

namespace cadnurbs {

std::vector<TriangleKey> oriented_triangle_keys(const std::vector<Eigen::Vector3d>& positions,
                                                const std::vector<std::array<int, 3>>& triangles) {
  std::vector<TriangleKey> keys;
  keys.reserve(triangles.size());
  for (const auto& t : triangles) {
    // The smallest of the three rotations: with two corners at one place (a collapsed triangle) the
    // smallest corner alone would not say where to start.
    TriangleKey best{};
    for (int first = 0; first < 3; ++first) {
      TriangleKey key{};
      for (int k = 0; k < 3; ++k)
        for (int c = 0; c < 3; ++c) key[3 * k + c] = positions[t[(first + k) % 3]][c];
      if (first == 0 || key < best) best = key;
    }
    keys.push_back(best);
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}

}  // namespace cadnurbs
