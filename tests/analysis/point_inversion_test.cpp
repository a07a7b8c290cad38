// point_inversion against closed forms on a cylinder: the nearest surface point of any point is its
// radial foot point, the nearest point of a trimming curve's image (a circular arc at one height) is
// the foot point on that arc, and both stay in the domain (or the parameter range) they are given.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/eval/point_inversion.hpp"
#include "analysis/eval/surface_evaluator.hpp"
#include "analysis_shapes.hpp"
#include "core/trim_segment_parameters.hpp"

namespace cadnurbs {
namespace {

constexpr double kRadius = 20, kHeight = 40;
// The distance is stationary at the foot point, so the iteration pins the distance to round-off but
// the point only to about sqrt(machine epsilon) times the size: 1e-6 here (5e-8 of the radius).
constexpr double kPointTolerance = 1e-6;

// A point at distance rho from the cylinder's axis, at angle theta (radians) and height z.
Eigen::Vector3d at(double rho, double theta, double z) { return {rho * std::cos(theta), rho * std::sin(theta), z}; }

TEST(PointInversion, ProjectionOntoACylinderIsTheRadialFootPoint) {
  const TrimmedSurface cylinder = test::quarter_cylinder(kRadius, kHeight);
  const SurfaceEvaluator e(cylinder.surface);
  for (double theta : {0.1, 0.5, 0.8, 1.4})
    for (double rho : {5.0, 19.0, 21.0, 35.0})
      for (double z : {3.0, 20.0, 37.0}) {
        const Eigen::Vector3d p = at(rho, theta, z);
        // Start from the middle of the domain, up to a quarter turn away.
        const SurfaceProjection s = project_to_surface(e, p, {0.5, 0.5});
        const Eigen::Vector3d foot = at(kRadius, theta, z);
        EXPECT_NEAR(s.distance, std::abs(rho - kRadius), 1e-9) << theta << " " << rho << " " << z;
        EXPECT_LT((s.point - foot).norm(), kPointTolerance) << theta << " " << rho << " " << z;
        EXPECT_LT((e.point(s.uv.x(), s.uv.y()) - s.point).norm(), 1e-12);
        EXPECT_NEAR(s.uv.y(), z / kHeight, kPointTolerance / kHeight);
      }
}

TEST(PointInversion, ProjectionBeyondTheDomainStopsAtItsEdge) {
  const TrimmedSurface cylinder = test::quarter_cylinder(kRadius, kHeight);
  const SurfaceEvaluator e(cylinder.surface);
  // Above the top (z = 50 > 40) at angle 0.6: the nearest point of the patch is on its top edge.
  const SurfaceProjection s = project_to_surface(e, at(kRadius, 0.6, 50), {0.5, 0.5});
  EXPECT_EQ(s.uv.y(), 1.0);
  EXPECT_NEAR(s.distance, 10.0, 1e-9);
  EXPECT_LT((s.point - at(kRadius, 0.6, kHeight)).norm(), kPointTolerance);
}

TEST(PointInversion, ProjectionOntoATrimCurveIsTheFootPointOnItsArc) {
  const TrimmedSurface cylinder = test::quarter_cylinder(kRadius, kHeight);
  const SurfaceEvaluator e(cylinder.surface);
  // The (u,v) line v = 0.25 across the whole domain: in 3D the quarter circle at z = 10.
  const TrimSegment line = Polyline2D{{{0.0, 0.25}, {1.0, 0.25}}};
  for (double theta : {0.2, 0.7, 1.3})
    for (double rho : {10.0, 25.0})
      for (double z : {0.0, 10.0, 33.0}) {
        const Eigen::Vector3d p = at(rho, theta, z);
        const CurveProjection c = project_to_trim_curve(e, line, p, 0.5, 0.0, 1.0);
        EXPECT_NEAR(c.distance, std::hypot(rho - kRadius, z - 10.0), 1e-9) << theta << " " << rho << " " << z;
        EXPECT_LT((c.point - at(kRadius, theta, 10.0)).norm(), kPointTolerance) << theta << " " << rho << " " << z;
        EXPECT_EQ(c.uv, segment_uv(line, c.t));
        EXPECT_NEAR(c.uv.y(), 0.25, 1e-15);
      }
  // Restricted to t in [0, 0.3], a point at 80 degrees projects onto the range's end.
  const CurveProjection end = project_to_trim_curve(e, line, at(kRadius, 80 * M_PI / 180, 10), 0.1, 0.0, 0.3);
  EXPECT_EQ(end.t, 0.3);
  const Eigen::Vector3d end_point = e.point(0.3, 0.25);
  EXPECT_LT((end.point - end_point).norm(), 1e-12);
}

}  // namespace
}  // namespace cadnurbs
