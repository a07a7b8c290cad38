#pragma once
// STEP's points, placements, curves and surfaces (ISO 10303-42 as AP203/AP214/AP242 use it) as core
// geometry, lengths in millimetres, angles in radians. Analytic curves keep their closed form (edges are
// trimmed and their pcurves found exactly from it); B-splines become NURBS as they are.
// Refuses (OutsideNativeSubset naming the entity): types outside the subset (OFFSET_SURFACE, TRIMMED_CURVE,
// 2D placements, ...), parameters of the wrong kind, B-splines whose knots, multiplicities or weights do
// not make a valid NURBS.
#include <Eigen/Core>
#include <variant>

#include "core/analytic_surface.hpp"
#include "core/axis_frame.hpp"
#include "core/nurbs_curve.hpp"
#include "core/nurbs_surface.hpp"
#include "formats/step/native/step_context.hpp"

namespace cadnurbs::step {

struct StepLine {
  Eigen::Vector3d point, direction;  // point + t direction (the VECTOR's orientation times its magnitude)
};
struct StepCircle {
  AxisFrame frame;
  double radius;
};
struct StepEllipse {
  AxisFrame frame;
  double semi_axis_1, semi_axis_2;
};
using StepCurve = std::variant<StepLine, StepCircle, StepEllipse, NurbsCurve>;
using StepSurface = std::variant<AnalyticSurface, NurbsSurface>;

Eigen::Vector3d read_point(const StepContext& context, EntityId point);          // CARTESIAN_POINT, scaled
Eigen::Vector3d read_direction(const StepContext& context, EntityId direction);  // DIRECTION, not normalised
AxisFrame read_frame(const StepContext& context, EntityId placement);            // AXIS2_PLACEMENT_3D

// Diagonal of the box of every 3D CARTESIAN_POINT in the file, in file units (0: none); points that do not
// read are left out (reading them where they are used refuses them).
double cartesian_points_size(const StepContext& context);

// LINE, CIRCLE, ELLIPSE, B_SPLINE_CURVE_WITH_KNOTS (rational as a complex instance); SURFACE_CURVE and
// SEAM_CURVE as their 3D curve (their pcurves are not used: the builder computes its own).
StepCurve read_curve(const StepContext& context, EntityId curve);

// PLANE, CYLINDRICAL_, CONICAL_, SPHERICAL_, TOROIDAL_SURFACE, SURFACE_OF_REVOLUTION,
// SURFACE_OF_LINEAR_EXTRUSION (of a curve read_curve reads), B_SPLINE_SURFACE_WITH_KNOTS (rational too).
StepSurface read_surface(const StepContext& context, EntityId surface);

// The curve as a NURBS (lines over [0, 1] from `point`, conics over one full turn from angle 0).
NurbsCurve curve_nurbs(const StepCurve& curve);

}  // namespace cadnurbs::step
