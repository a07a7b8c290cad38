#include "report/storage_crossover.hpp"

#include <algorithm>
#include <cmath>

namespace cadnurbs {

Crossover storage_crossover(std::vector<BytesAtDeviation> mesh, double nurbs_bytes) {
  Crossover result;
  if (mesh.empty()) return result;
  std::sort(mesh.begin(), mesh.end(), [](const auto& a, const auto& b) { return a.deviation > b.deviation; });
  // Coarse D first: the mesh is smallest there. The first point where it is at least the NURBS closes
  // the bracket.
  if (mesh.front().bytes >= nurbs_bytes) {
    result.mesh_larger_everywhere = true;
    return result;
  }
  for (std::size_t i = 1; i < mesh.size(); ++i) {
    if (mesh[i].bytes < nurbs_bytes) continue;
    const double x0 = std::log(mesh[i - 1].deviation), x1 = std::log(mesh[i].deviation);
    const double y0 = std::log(mesh[i - 1].bytes), y1 = std::log(mesh[i].bytes), y = std::log(nurbs_bytes);
    const double t = y1 > y0 ? (y - y0) / (y1 - y0) : 1.0;
    result.deviation = std::exp(x0 + t * (x1 - x0));
    return result;
  }
  return result;
}

}  // namespace cadnurbs
