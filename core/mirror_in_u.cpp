#include "core/mirror_in_u.hpp"

#include <algorithm>

namespace cadnurbs {

void mirror_in_u(TrimmedSurface& face) {
  NurbsSurface& s = face.surface;
  const double a = s.u_start(), b = s.u_end();
  for (int j = 0; j < s.v_count; ++j) {
    std::reverse(s.points.begin() + s.index(0, j), s.points.begin() + s.index(0, j) + s.u_count);
    if (s.is_rational()) std::reverse(s.weights.begin() + s.index(0, j), s.weights.begin() + s.index(0, j) + s.u_count);
  }
  const std::vector<double> k = s.u_knots;
  for (std::size_t m = 0; m < k.size(); ++m) s.u_knots[m] = a + b - k[k.size() - 1 - m];
  for (auto& loop : face.loops)
    for (auto& segment : loop.segments) {
      if (auto* c = std::get_if<NurbsCurve>(&segment)) {
        for (auto& p : c->points) p.x() = a + b - p.x();
      } else {
        for (auto& p : std::get<Polyline2D>(segment).points) p.x() = a + b - p.x();
      }
    }
}

}  // namespace cadnurbs
