// axis_frame: STEP's AXIS2_PLACEMENT_3D rules, and to_world / to_local as inverses.
#include "core/axis_frame.hpp"

#include <gtest/gtest.h>

#include "core/geometry_error.hpp"

namespace cadnurbs {
namespace {

void expect_orthonormal_right_handed(const AxisFrame& f) {
  EXPECT_NEAR(f.x.norm(), 1, 1e-15);
  EXPECT_NEAR(f.y.norm(), 1, 1e-15);
  EXPECT_NEAR(f.z.norm(), 1, 1e-15);
  EXPECT_NEAR(f.x.dot(f.y), 0, 1e-15);
  EXPECT_NEAR(f.x.dot(f.z), 0, 1e-15);
  EXPECT_LT((f.x.cross(f.y) - f.z).norm(), 1e-15);
}

TEST(AxisFrame, RefDirectionIsMadeOrthogonalToTheAxis) {
  const AxisFrame f = axis_frame({1, 2, 3}, Eigen::Vector3d(0, 0, 2), Eigen::Vector3d(3, 0, 4), "axis2");
  expect_orthonormal_right_handed(f);
  EXPECT_LT((f.z - Eigen::Vector3d(0, 0, 1)).norm(), 1e-15);
  EXPECT_LT((f.x - Eigen::Vector3d(1, 0, 0)).norm(), 1e-15);
  EXPECT_LT((f.y - Eigen::Vector3d(0, 1, 0)).norm(), 1e-15);
  EXPECT_EQ(f.origin, Eigen::Vector3d(1, 2, 3));
}

TEST(AxisFrame, MissingDirectionsFollowIso10303_42) {
  const AxisFrame standard = axis_frame({0, 0, 0}, std::nullopt, std::nullopt, "axis2");
  EXPECT_EQ(standard.x, Eigen::Vector3d(1, 0, 0));
  EXPECT_EQ(standard.y, Eigen::Vector3d(0, 1, 0));
  EXPECT_EQ(standard.z, Eigen::Vector3d(0, 0, 1));
  const AxisFrame tilted = axis_frame({0, 0, 0}, Eigen::Vector3d(1, 0, 1), std::nullopt, "axis2");
  expect_orthonormal_right_handed(tilted);
  EXPECT_LT((tilted.x - Eigen::Vector3d(1, 0, -1).normalized()).norm(), 1e-15);  // (1,0,0) projected
  const AxisFrame along_x = axis_frame({0, 0, 0}, Eigen::Vector3d(-5, 0, 0), std::nullopt, "axis2");
  expect_orthonormal_right_handed(along_x);
  EXPECT_EQ(along_x.x, Eigen::Vector3d(0, 1, 0));
}

TEST(AxisFrame, WorldAndLocalAreInverses) {
  const AxisFrame f = axis_frame({1, -2, 0.5}, Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(-1, 0.5, 2), "axis2");
  expect_orthonormal_right_handed(f);
  const Eigen::Vector3d p(0.3, -7, 2.25);
  EXPECT_LT((to_world(f, to_local(f, p)) - p).norm(), 1e-14);
  EXPECT_LT((to_local(f, f.origin + 2 * f.y) - Eigen::Vector3d(0, 2, 0)).norm(), 1e-14);
}

TEST(AxisFrame, RefusesZeroAxisAndParallelReference) {
  try {
    axis_frame({0, 0, 0}, Eigen::Vector3d(0, 0, 0), std::nullopt, "#12");
    FAIL();
  } catch (const GeometryError& e) {
    EXPECT_EQ(e.entity(), "#12");
    EXPECT_NE(e.reason().find("axis is zero"), std::string::npos);
  }
  try {
    axis_frame({0, 0, 0}, Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 0, -3), "#13");
    FAIL();
  } catch (const GeometryError& e) {
    EXPECT_NE(e.reason().find("parallel"), std::string::npos);
  }
  EXPECT_THROW(axis_frame({0, 0, 0}, std::nullopt, Eigen::Vector3d(0, 0, 0), "#14"), GeometryError);
}

}  // namespace
}  // namespace cadnurbs
