#include "analysis/mesh/largest_corner_move.hpp"

#include <algorithm>

namespace cadnurbs {

std::optional<double> largest_corner_move(const TriangleMesh& written, const TriangleMesh& read_back) {
  if (written.triangles.size() != read_back.triangles.size()) return std::nullopt;
  double largest = 0;
  for (std::size_t t = 0; t < written.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      largest = std::max(largest, (written.positions[written.triangles[t][k]] -
                                   read_back.positions[read_back.triangles[t][k]]).norm());
  return largest;
}

}  // namespace cadnurbs
