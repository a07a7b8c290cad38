#pragma once
// Whether a (u,v) segment touches an axis-aligned box (internal to tessellation): which grid cells a
// trimming loop passes through (grid planning) and which grid points lie too close to a loop (face
// meshing).
#include <Eigen/Core>

namespace cadnurbs::tessellation {

// True when segment ab meets the closed box [x0, x1] x [y0, y1] (Liang-Barsky clipping; touching
// counts).
bool segment_meets_box(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double x0, double x1, double y0, double y1);

}  // namespace cadnurbs::tessellation
