#pragma once
// Scenes built by hand for the VRML tests, each exercising one part of the mapping.
#include "core/scene.hpp"
#include "formats/vrml/vrml_write_options.hpp"

namespace cadnurbs::vrml_test {

// Default writer options with the given encoding.
inline VrmlWriteOptions with_encoding(VrmlEncoding encoding) {
  VrmlWriteOptions o;
  o.encoding = encoding;
  return o;
}

// Quarter of a cylinder of radius 10 about Z, height 20: rational quadratic in u (middle weight
// cos 45°), linear in v.
NurbsSurface quarter_cylinder();

// Circle of radius r around c in (u,v) as four rational quadratic arcs, counter-clockwise.
TrimLoop circle_loop(const Eigen::Vector2d& c, double r);

// A planar 100 x 100 patch whose domain [0,1]² is trimmed to a circle (four NurbsCurve2D arcs) with a
// square hole (one clockwise Polyline2D).
TrimmedSurface trimmed_plate();

// An octahedron with per-corner normals (flat: each face's normal at its three corners).
TriangleMesh octahedron_with_normals();

// A rational 3D curve: a semicircle of radius 5 in the XY plane (two quarter arcs).
NurbsCurve semicircle_curve();

// One shape per scene.
Scene single_shape_scene(Geometry geometry, const std::string& name = "part");

// Two levels: root "Assembly" (coloured) holding "Bracket 1" (translated and rotated, red, a cylinder
// inheriting red and a trimmed plate with its own colour) and another "Bracket 1" (non-uniform scale
// with rotation, no colour of its own, a cylinder inheriting the root's colour) whose child "Ünïcode
// mesh" holds a mesh. Names need sanitising and making unique.
Scene assembly_scene(bool with_curve);

}  // namespace cadnurbs::vrml_test
