#include "core/subd_control_net.hpp"

#include <algorithm>
#include <set>
#include <utility>

#include "core/geometry_error.hpp"

namespace cadnurbs {

void validate(const SubdControlNet& net, const std::string& entity) {
  const int n = static_cast<int>(net.points.size());
  for (int i = 0; i < n; ++i)
    if (!net.points[i].allFinite()) throw GeometryError(entity, "point " + std::to_string(i) + " is not finite");
  auto in_range = [&](int k, const std::string& what) {
    if (k < 0 || k >= n)
      throw GeometryError(entity, what + " uses point " + std::to_string(k) + " of " + std::to_string(n));
  };
  std::set<std::pair<int, int>> face_edges;
  for (size_t f = 0; f < net.faces.size(); ++f) {
    const auto& face = net.faces[f];
    const std::string what = "face " + std::to_string(f);
    if (face.size() < 3) throw GeometryError(entity, what + " has " + std::to_string(face.size()) + " points");
    for (int k : face) in_range(k, what);
    std::vector<int> sorted = face;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
      throw GeometryError(entity, what + " repeats a point");
    for (size_t k = 0; k < face.size(); ++k) {
      const int a = face[k], b = face[(k + 1) % face.size()];
      face_edges.insert({std::min(a, b), std::max(a, b)});
    }
  }
  for (size_t e = 0; e < net.crease_edges.size(); ++e) {
    const auto [a, b] = net.crease_edges[e];
    const std::string what = "crease edge " + std::to_string(e);
    in_range(a, what);
    in_range(b, what);
    if (!face_edges.count({std::min(a, b), std::max(a, b)})) throw GeometryError(entity, what + " is no face's edge");
  }
  for (int k : net.corner_points) in_range(k, "corner");
}

}  // namespace cadnurbs
