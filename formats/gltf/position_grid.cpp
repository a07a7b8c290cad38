#include "formats/gltf/position_grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cadnurbs {

std::array<std::uint32_t, 3> PositionGrid::quantised(const Eigen::Vector3d& p) const {
  const double top = std::ldexp(1.0, bits) - 1;
  std::array<std::uint32_t, 3> q{};
  for (int axis = 0; axis < 3; ++axis)
    q[axis] = static_cast<std::uint32_t>(std::clamp(std::round((p[axis] - origin[axis]) / step), 0.0, top));
  return q;
}

Eigen::Vector3d PositionGrid::position(const std::array<std::uint32_t, 3>& q) const {
  return origin + step * Eigen::Vector3d(q[0], q[1], q[2]);
}

PositionGrid position_grid(const Eigen::AlignedBox3d& box, int bits) {
  if (bits < 1 || bits > 30) throw std::invalid_argument("position grid: " + std::to_string(bits) + " bits is outside 1..30");
  PositionGrid grid;
  grid.bits = bits;
  if (box.isEmpty()) return grid;
  grid.origin = box.min();
  const double extent = box.sizes().maxCoeff();
  // 1e-6 beyond the box: Draco quantises the float32 of each coordinate, which may lie 2^-24 of it outside.
  if (extent > 0) grid.step = extent * (1 + 1e-6) / (std::ldexp(1.0, bits) - 1);
  return grid;
}

}  // namespace cadnurbs
