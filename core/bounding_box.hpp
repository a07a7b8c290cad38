#pragma once
// Axis-aligned bounding boxes of control nets and meshes, in world coordinates.
#include <Eigen/Geometry>

#include "core/scene.hpp"

namespace cadnurbs {

// Box of every control point and mesh vertex (control nets bound their NURBS, by the convex hull property).
Eigen::AlignedBox3d scene_bounding_box(const Scene& scene);

// Box of a mesh's positions (empty for a mesh without positions).
Eigen::AlignedBox3d mesh_bounding_box(const TriangleMesh& mesh);

}  // namespace cadnurbs
