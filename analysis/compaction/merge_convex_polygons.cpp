#include "analysis/compaction/merge_convex_polygons.hpp"

#include <map>

#include "core/polygon_2d.hpp"

namespace cadnurbs {

std::vector<std::vector<int>> merge_convex_polygons(const std::vector<Eigen::Vector2d>& points,
                                                    const std::vector<std::array<int, 3>>& triangles,
                                                    double tolerance) {
  std::vector<std::vector<int>> polygons;
  for (const auto& t : triangles) polygons.push_back({t[0], t[1], t[2]});
  std::vector<bool> alive(polygons.size(), true);
  // Directed edge -> polygon holding it. Kept up to date as polygons merge.
  std::map<std::pair<int, int>, size_t> owner;
  for (size_t p = 0; p < polygons.size(); ++p)
    for (size_t k = 0; k < 3; ++k) owner[{polygons[p][k], polygons[p][(k + 1) % 3]}] = p;

  for (bool merged_any = true; merged_any;) {
    merged_any = false;
    for (size_t p = 0; p < polygons.size(); ++p) {
      if (!alive[p]) continue;
      for (size_t k = 0; k < polygons[p].size();) {
        const std::vector<int>& P = polygons[p];
        const int a = P[k], b = P[(k + 1) % P.size()];
        auto other = owner.find({b, a});
        if (other == owner.end() || other->second == p || !alive[other->second]) {
          ++k;
          continue;
        }
        const size_t q = other->second;
        const std::vector<int>& Q = polygons[q];
        // Q runs ... b -> a ...; the union runs P up to a, then Q from a round to b, then P from b.
        size_t qa = 0;
        while (Q[qa] != a) ++qa;
        std::vector<int> path;  // Q's corners strictly between a and b, going a -> ... -> b in Q
        for (size_t m = (qa + 1) % Q.size(); Q[m] != b; m = (m + 1) % Q.size()) path.push_back(Q[m]);
        const int before_a = P[(k + P.size() - 1) % P.size()], after_b = P[(k + 2) % P.size()];
        const int after_a = path.empty() ? b : path.front(), before_b = path.empty() ? a : path.back();
        if (!convex_corner(points[before_a], points[a], points[after_a], tolerance) ||
            !convex_corner(points[before_b], points[b], points[after_b], tolerance)) {
          ++k;
          continue;
        }
        std::vector<int> merged;
        for (size_t m = 0; m <= k; ++m) merged.push_back(P[m]);  // ... up to a
        merged.insert(merged.end(), path.begin(), path.end());
        for (size_t m = k + 1; m < P.size(); ++m) merged.push_back(P[m]);  // b ...
        owner.erase({a, b});
        owner.erase({b, a});
        for (size_t m = 0; m < merged.size(); ++m) owner[{merged[m], merged[(m + 1) % merged.size()]}] = p;
        polygons[p] = std::move(merged);
        alive[q] = false;
        merged_any = true;
        k = 0;  // p changed: look at its edges again
      }
    }
  }
  std::vector<std::vector<int>> out;
  for (size_t p = 0; p < polygons.size(); ++p)
    if (alive[p]) out.push_back(std::move(polygons[p]));
  return out;
}

}  // namespace cadnurbs
