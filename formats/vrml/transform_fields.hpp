#pragma once
// An affine transform as the fields of a VRML/X3D Transform node:
//   M = T * C * R * SR * S * SR^-1 * C^-1   (C, the center, is always zero when we write).
#include <Eigen/Geometry>

namespace cadnurbs {

struct TransformFields {
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  Eigen::AngleAxisd rotation{0.0, Eigen::Vector3d::UnitZ()};
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
  Eigen::AngleAxisd scale_orientation{0.0, Eigen::Vector3d::UnitZ()};
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
};

// Any non-singular affine map as Transform fields (polar decomposition by SVD, so shear and non-uniform
// scale are exact through scaleOrientation). A mirror gets one negative scale factor. The scale
// orientation is the identity when the scale is uniform. Refuses (std::invalid_argument) singular or
// non-finite transforms.
TransformFields decompose_transform(const Eigen::Affine3d& transform);

// The affine map the fields describe (with the center, for Transform nodes read from other files).
Eigen::Affine3d compose_transform(const TransformFields& fields);

}  // namespace cadnurbs
