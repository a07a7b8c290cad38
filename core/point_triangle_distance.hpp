#pragma once
// Distance from a point to a solid triangle (or, when the triangle has collapsed, to its longest
// side) in 3D: the closest-point regions of Ericson, Real-Time Collision Detection, 5.1.5.
#include <Eigen/Geometry>

namespace cadnurbs {

double point_triangle_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                               const Eigen::Vector3d& c);

// Distance from p to the segment [a, b].
double point_segment_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b);

}  // namespace cadnurbs
