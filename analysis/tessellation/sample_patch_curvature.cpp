#include "analysis/tessellation/sample_patch_curvature.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "analysis/tessellation/surface_normal.hpp"

namespace cadnurbs::tessellation {

PatchCurvature sample_patch_curvature(const SurfaceEvaluator& e, double u0, double u1, double v0, double v1) {
  PatchCurvature out;
  double fuu = 0, fuv = 0, fvv = 0;  // whole second derivatives, for a patch without any normal
  bool any_normal = false;
  auto at = [](double start, double end, int k) { return k < 3 ? start + (end - start) * k / 3 : std::nextafter(end, start); };
  for (int b = 0; b <= 3; ++b)
    for (int a = 0; a <= 3; ++a) {
      const SurfaceJet jet = e.jet(at(u0, u1, a), at(v0, v1, b), 2);
      out.su = std::max(out.su, jet.su.norm()), out.sv = std::max(out.sv, jet.sv.norm());
      fuu = std::max(fuu, jet.suu.norm()), fuv = std::max(fuv, jet.suv.norm()), fvv = std::max(fvv, jet.svv.norm());
      // Points without a normal (poles) are skipped.
      const Eigen::Vector3d n = jet.su.cross(jet.sv);
      if (!has_normal(jet)) continue;
      const Eigen::Vector3d un = n.normalized();
      out.uu = std::max(out.uu, std::abs(un.dot(jet.suu)));
      out.uv = std::max(out.uv, std::abs(un.dot(jet.suv)));
      out.vv = std::max(out.vv, std::abs(un.dot(jet.svv)));
      any_normal = true;
      // n_v lies along the tangent perpendicular to S_v, with n_v . S_u = -L_uv, so |n_v| = |L_uv| /
      // |S_u across S_v| (likewise for u). Developable surfaces (cylinders, cones) have L_uv = 0.
      const double twist = std::abs(un.dot(jet.suv));
      const double su_across = n.norm() / std::max(jet.sv.norm(), 1e-300);
      const double sv_across = n.norm() / std::max(jet.su.norm(), 1e-300);
      if (su_across > 0) out.turn_v = std::max(out.turn_v, twist / su_across);
      if (sv_across > 0) out.turn_u = std::max(out.turn_u, twist / sv_across);
    }
  if (!any_normal) out.uu = fuu, out.uv = fuv, out.vv = fvv;
  return out;
}

}  // namespace cadnurbs::tessellation
