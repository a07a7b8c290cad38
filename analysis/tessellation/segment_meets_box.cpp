#include "analysis/tessellation/segment_meets_box.hpp"

#include <algorithm>

namespace cadnurbs::tessellation {

bool segment_meets_box(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double x0, double x1, double y0, double y1) {
  double t0 = 0, t1 = 1;
  const Eigen::Vector2d d = b - a;
  const double p[4] = {-d.x(), d.x(), -d.y(), d.y()};
  const double q[4] = {a.x() - x0, x1 - a.x(), a.y() - y0, y1 - a.y()};
  for (int k = 0; k < 4; ++k) {
    if (p[k] == 0) {
      if (q[k] < 0) return false;
    } else {
      const double r = q[k] / p[k];
      if (p[k] < 0) t0 = std::max(t0, r);
      else t1 = std::min(t1, r);
      if (t0 > t1) return false;
    }
  }
  return true;
}

}  // namespace cadnurbs::tessellation
