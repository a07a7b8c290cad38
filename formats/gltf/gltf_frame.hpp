#pragma once
// glTF's frame: lengths in metres, +Y up, right-handed (glTF 2.0, "Coordinate System and Units").
// Our scenes hold lengths in scene.unit with +Z up, as CAD files do.
#include <Eigen/Core>

#include "core/scene.hpp"

namespace cadnurbs {

// The linear map from scene coordinates to glTF's: scale by unit.millimetres / 1000 (to metres), then a
// quarter turn about +X taking +Z to +Y and +Y to -Z: (x, y, z) -> (x, z, -y). A rotation, so nothing is
// mirrored. Refuses (std::invalid_argument) a unit that is not a positive finite length.
Eigen::Matrix3d gltf_frame(const LengthUnit& unit);

}  // namespace cadnurbs
