// planar_polygon_surface: the polygon's corners come back from the surface, facing the Newell normal.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "core/nurbs_surface.hpp"
#include "core/planar_polygon_surface.hpp"

namespace cadnurbs {
namespace {

TEST(PlanarPolygonSurface, TiltedLShapeGivesItsCornersBack) {
  // An L-shaped hexagon (area 3) counter-clockwise in its plane, rotated and moved off the origin.
  const std::vector<Eigen::Vector2d> flat = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  const Eigen::Affine3d place = Eigen::Translation3d(5, -3, 2) * Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized());
  std::vector<Eigen::Vector3d> corners;
  for (const auto& p : flat) corners.push_back(place * Eigen::Vector3d(p.x(), p.y(), 0));
  const auto face = planar_polygon_surface(corners);
  ASSERT_TRUE(face.has_value());
  ASSERT_EQ(face->loops.size(), 1u);
  const TrimLoop& loop = face->loops[0];
  ASSERT_EQ(loop.segments.size(), 6u);
  EXPECT_NEAR(loop_signed_area(loop), 3.0, 1e-12);  // counter-clockwise in (u,v), area kept
  for (size_t i = 0; i < 6; ++i) {
    const Eigen::Vector2d uv = segment_start(loop.segments[i]);
    EXPECT_LT((surface_point(face->surface, uv.x(), uv.y()) - corners[i]).norm(), 1e-12) << "corner " << i;
  }
  const auto d = surface_derivatives(face->surface, segment_start(loop.segments[0]).x(), segment_start(loop.segments[0]).y(), 1);
  const Eigen::Vector3d normal = d[1][0].cross(d[0][1]).normalized();
  EXPECT_NEAR(normal.dot(place.linear() * Eigen::Vector3d::UnitZ()), 1.0, 1e-12);
}

TEST(PlanarPolygonSurface, NoAreaNoSurface) {
  EXPECT_FALSE(planar_polygon_surface({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}).has_value());
  EXPECT_FALSE(planar_polygon_surface({{0, 0, 0}, {1, 0, 0}}).has_value());
}

}  // namespace
}  // namespace cadnurbs
