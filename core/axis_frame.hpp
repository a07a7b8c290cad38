#pragma once
// A right-handed orthonormal frame: STEP's AXIS2_PLACEMENT_3D (ISO 10303-42, 4.4.5-4.4.6: the entity
// and its build_axes / first_proj_axis functions).
//
// In:  an origin, an optional axis and an optional ref_direction (any lengths).
// Out: z = axis normalised, (0,0,1) when missing; x = ref_direction with its z part removed
//      (Gram-Schmidt) and normalised; y = z x x. Missing ref_direction: first_proj_axis's rule,
//      (1,0,0) made orthogonal to z, or (0,1,0) when z is parallel to (1,0,0) (either sense).
// Refuses (GeometryError(entity, reason)): a zero or non-finite axis or ref_direction, a ref_direction
//      parallel to the axis (its part orthogonal to z below 1e-12 of its length: no direction left).
#include <Eigen/Geometry>
#include <optional>
#include <string>

namespace cadnurbs {

struct AxisFrame {
  Eigen::Vector3d origin{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};  // right-handed orthonormal
};

AxisFrame axis_frame(const Eigen::Vector3d& origin, const std::optional<Eigen::Vector3d>& axis,
                     const std::optional<Eigen::Vector3d>& ref_direction, const std::string& entity);

// origin + local.x x + local.y y + local.z z, and its inverse (the frame is orthonormal: transpose).
Eigen::Vector3d to_world(const AxisFrame& frame, const Eigen::Vector3d& local);
Eigen::Vector3d to_local(const AxisFrame& frame, const Eigen::Vector3d& world);

}  // namespace cadnurbs
