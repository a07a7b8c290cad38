#include "analysis/tessellation/domain_loop.hpp"

#include <Eigen/Geometry>
#include <utility>

namespace cadnurbs::tessellation {

bool sides_coincide(const SurfaceEvaluator& e, const Eigen::Vector2d& a0, const Eigen::Vector2d& a1,
                    const Eigen::Vector2d& b0, const Eigen::Vector2d& b1, double tolerance) {
  for (int k = 0; k <= 16; ++k) {
    const double s = k / 16.0;
    const Eigen::Vector2d p = (1 - s) * a0 + s * a1, q = (1 - s) * b0 + s * b1;
    if ((e.point(p.x(), p.y()) - e.point(q.x(), q.y())).norm() > tolerance) return false;
  }
  return true;
}

}  // namespace cadnurbs::tessellation
