#pragma once
// Analytic shapes built by hand for the core tests.
#include "core/nurbs_curve.hpp"
#include "core/nurbs_surface.hpp"

namespace cadnurbs::test {

// Quarter circle of `radius` around the origin in the XY plane: one rational quadratic Bézier arc.
NurbsCurve quarter_circle(double radius);

// Full circle from four quarter arcs joined by double knots (Piegl & Tiller's 9-point circle).
NurbsCurve full_circle(double radius);

// Quarter of a cylinder of `radius` about Z, from z = 0 to `height`: u along the arc, v along Z.
NurbsSurface quarter_cylinder(double radius, double height);

}  // namespace cadnurbs::test
