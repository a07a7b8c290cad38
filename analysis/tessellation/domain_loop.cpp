#include "analysis/tessellation/domain_loop.hpp"

#include <Eigen/Geometry>
#include <utility>

namespace cadnurbs::tessellation {

TrimLoop domain_loop(const NurbsSurface& s) {
  const Eigen::Vector2d a(s.u_start(), s.v_start()), b(s.u_end(), s.v_start()), c(s.u_end(), s.v_end()),
      d(s.u_start(), s.v_end());
  TrimLoop loop;
  for (const auto& [p, q] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, d}, std::pair{d, a}})
    loop.segments.emplace_back(Polyline2D{{p, q}});
  return loop;
}

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
