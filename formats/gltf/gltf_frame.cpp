#include "formats/gltf/gltf_frame.hpp"

#include <cmath>
#include <stdexcept>

namespace cadnurbs {

Eigen::Matrix3d gltf_frame(const LengthUnit& unit) {
  if (!(unit.millimetres > 0) || !std::isfinite(unit.millimetres))
    throw std::invalid_argument("glTF: the scene unit '" + unit.name + "' is not a positive length");
  Eigen::Matrix3d z_up_to_y_up;
  z_up_to_y_up << 1, 0, 0,  //
      0, 0, 1,              //
      0, -1, 0;
  return (unit.millimetres / 1000.0) * z_up_to_y_up;
}

}  // namespace cadnurbs
