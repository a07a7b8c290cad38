#include "analysis/tessellation/surface_normal.hpp"

#include <Eigen/Geometry>

namespace cadnurbs::tessellation {

bool has_normal(const SurfaceJet& j) {
  return j.su.cross(j.sv).norm() > 1e-9 * (j.su.squaredNorm() + j.sv.squaredNorm());
}

Eigen::Vector3d normal_at(const SurfaceEvaluator& e, const Eigen::Vector2d& uv) {
  const double du = e.u_end() - e.u_start(), dv = e.v_end() - e.v_start();
  for (double step : {0.0, 1e-7, 1e-5, 1e-3}) {
    const double u = uv.x() + (uv.x() < e.u_start() + 0.5 * du ? step : -step) * du;
    const double v = uv.y() + (uv.y() < e.v_start() + 0.5 * dv ? step : -step) * dv;
    const SurfaceJet j = e.jet(u, v, 1);
    if (has_normal(j)) return j.su.cross(j.sv).normalized();
  }
  return Eigen::Vector3d::Zero();
}

}  // namespace cadnurbs::tessellation
