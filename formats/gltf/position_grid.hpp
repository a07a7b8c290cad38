#pragma once
// The one quantisation grid of a glTF file's positions, shared by every primitive (Draco's explicit
// quantisation and meshoptimizer's integer positions alike), so that a point two primitives share
// stays one point after decoding: a grid per primitive would open cracks along their common edges.
#include <Eigen/Geometry>
#include <array>
#include <cstdint>

namespace cadnurbs {

struct PositionGrid {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // the box's smallest corner
  double step = 1;                                   // the same along every axis
  int bits = 16;                                     // grid values run over 0 .. 2^bits - 1

  // The nearest grid point's integer coordinates (clamped to the grid).
  std::array<std::uint32_t, 3> quantised(const Eigen::Vector3d& p) const;
  // The point the decoder makes of them: origin + step * q.
  Eigen::Vector3d position(const std::array<std::uint32_t, 3>& q) const;
};

// The grid of 2^bits values per axis over the cube on `box`'s smallest corner whose side is the box's
// largest extent (a hair larger, so float rounding cannot push a point off the grid). Any point of the
// box is then within step / 2 of its grid point along each axis. An empty or single-point box gets
// step 1. Refuses (std::invalid_argument) bits outside 1..30.
PositionGrid position_grid(const Eigen::AlignedBox3d& box, int bits);

}  // namespace cadnurbs
