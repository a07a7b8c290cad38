#pragma once
// The camera a written file opens with. Passed explicitly, it lets a tessellated mesh of a part be
// written with exactly the Viewpoint of its NURBS file, so renders of the two compare pixel by pixel.
#include <Eigen/Geometry>

namespace cadnurbs {

struct Viewpoint {
  Eigen::Vector3d position = Eigen::Vector3d(0, 0, 10);               // VRML's default camera
  Eigen::AngleAxisd orientation{0.0, Eigen::Vector3d::UnitZ()};        // rotation of the default view along -Z
  double field_of_view = 0.785398;                                     // radians, of the smaller window side
};

// A camera on the (1, 1, 1) diagonal from the box centre, looking at the centre with +Y up, at the
// distance where the box's bounding sphere just fills the field of view. An empty box gives VRML's default
// camera; a box of zero size is framed as if it had radius 1.
Viewpoint framing_viewpoint(const Eigen::AlignedBox3d& box, double field_of_view = 0.785398);

}  // namespace cadnurbs
