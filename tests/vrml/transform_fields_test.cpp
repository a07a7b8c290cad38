// Affine maps as Transform fields and back; the framing Viewpoint.
#include <gtest/gtest.h>

#include <cmath>

#include "formats/vrml/transform_fields.hpp"
#include "formats/vrml/viewpoint.hpp"

namespace cadnurbs {
namespace {

void expect_round_trip(const Eigen::Affine3d& m) {
  const TransformFields f = decompose_transform(m);
  const Eigen::Affine3d back = compose_transform(f);
  EXPECT_LE((back.matrix() - m.matrix()).cwiseAbs().maxCoeff(), 1e-12) << m.matrix();
}

TEST(TransformFields, RigidMotionHasUnitScale) {
  const Eigen::Affine3d m = Eigen::Translation3d(1, 2, 3) * Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized());
  const TransformFields f = decompose_transform(m);
  EXPECT_LE((f.scale - Eigen::Vector3d::Ones()).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_NEAR(f.rotation.angle(), 0.7, 1e-12);
  EXPECT_LE((f.rotation.axis() - Eigen::Vector3d(1, 2, 3).normalized()).norm(), 1e-12);
  EXPECT_EQ(f.scale_orientation.angle(), 0.0);
  expect_round_trip(m);
}

TEST(TransformFields, UniformScaleNeedsNoScaleOrientation) {
  const Eigen::Affine3d m(Eigen::AngleAxisd(2.0, Eigen::Vector3d::UnitX()) * Eigen::Scaling(2.5));
  const TransformFields f = decompose_transform(m);
  EXPECT_LE((f.scale - Eigen::Vector3d::Constant(2.5)).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(f.scale_orientation.angle(), 0.0);
  expect_round_trip(m);
}

TEST(TransformFields, ShearAndNonUniformScaleAreExact) {
  Eigen::Affine3d m = Eigen::Affine3d::Identity();
  m.linear() << 1.0, 0.5, 0.0, 0.0, 2.0, 0.3, 0.1, 0.0, 0.7;
  m.translation() << -4, 5, 6;
  expect_round_trip(m);
  expect_round_trip(Eigen::Affine3d(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()) * Eigen::Scaling(1.5, 1.0, 0.5) *
                                    Eigen::AngleAxisd(-0.3, Eigen::Vector3d::UnitZ())));
}

TEST(TransformFields, MirrorBecomesNegativeScale) {
  const Eigen::Affine3d m(Eigen::Scaling(1.0, -1.0, 1.0));
  const TransformFields f = decompose_transform(m);
  EXPECT_LT(f.scale.prod(), 0.0);
  expect_round_trip(m);
}

TEST(TransformFields, RefusesSingularTransforms) {
  EXPECT_THROW(decompose_transform(Eigen::Affine3d(Eigen::Scaling(1.0, 0.0, 1.0))), std::invalid_argument);
  Eigen::Affine3d nan = Eigen::Affine3d::Identity();
  nan(0, 3) = std::nan("");
  EXPECT_THROW(decompose_transform(nan), std::invalid_argument);
}

TEST(TransformFields, CenterIsHonouredWhenComposing) {
  TransformFields f;
  f.rotation = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ());
  f.center = Eigen::Vector3d(1, 0, 0);
  // A quarter turn about the vertical line through (1, 0, 0) keeps that point and moves the origin.
  EXPECT_LE((compose_transform(f) * Eigen::Vector3d(1, 0, 0) - Eigen::Vector3d(1, 0, 0)).norm(), 1e-12);
  EXPECT_LE((compose_transform(f) * Eigen::Vector3d(0, 0, 0) - Eigen::Vector3d(1, -1, 0)).norm(), 1e-12);
}

TEST(FramingViewpoint, SeesTheWholeBoxFromTheDiagonal) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d(-10, 0, 5), Eigen::Vector3d(30, 20, 15));
  const Viewpoint view = framing_viewpoint(box);
  const Eigen::Vector3d centre = box.center();
  const double radius = 0.5 * box.diagonal().norm();
  // On the (1,1,1) diagonal, at radius / sin(fov/2).
  const Eigen::Vector3d offset = view.position - centre;
  EXPECT_LE((offset.normalized() - Eigen::Vector3d(1, 1, 1).normalized()).norm(), 1e-12);
  EXPECT_NEAR(offset.norm(), radius / std::sin(0.785398 / 2), 1e-9);
  // Looking at the centre: the rotated -Z is the direction to the centre; the rotated +Y has no roll
  // (it lies in the plane of the view direction and world up).
  const Eigen::Vector3d forward = view.orientation * Eigen::Vector3d(0, 0, -1);
  EXPECT_LE((forward - (centre - view.position).normalized()).norm(), 1e-12);
  const Eigen::Vector3d up = view.orientation * Eigen::Vector3d::UnitY();
  EXPECT_GT(up.y(), 0.0);
  EXPECT_NEAR(up.dot(forward.cross(Eigen::Vector3d::UnitY())), 0.0, 1e-12);
  // Every corner is inside the cone of the field of view.
  for (int c = 0; c < 8; ++c) {
    const Eigen::Vector3d to_corner = box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)) - view.position;
    EXPECT_LE(std::acos(to_corner.normalized().dot(forward)), 0.785398 / 2 + 1e-12);
  }
}

TEST(FramingViewpoint, EmptyBoxGivesTheDefaultCamera) {
  const Viewpoint view = framing_viewpoint(Eigen::AlignedBox3d());
  EXPECT_EQ(view.position, Eigen::Vector3d(0, 0, 10));
  EXPECT_EQ(view.orientation.angle(), 0.0);
}

}  // namespace
}  // namespace cadnurbs
