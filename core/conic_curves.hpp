#pragma once
// STEP's LINE, CIRCLE and ELLIPSE (ISO 10303-42) over a parameter range, as exact NURBS curves.
// Sources: Piegl & Tiller, The NURBS Book, 2nd ed., §7.3-7.5 (the circle as rational quadratic arcs,
// A7.1) and §7.6 / §4.3 (a NURBS curve's affine image is the NURBS with the same knots and weights and
// the mapped control points: so the ellipse is the circle's image under (x, y) -> (r1 x, r2 y)).
//
// Circles and ellipses take their parameters from core/arc_parameterization: the curve's parameter is
// arc_parameter(arc_spans(a0, a1), a) at angle a, equal to the angle at every knot. When a1 < a0 the arc
// runs clockwise: it is the arc over [a1, a0] reversed (core reversed()), so its domain is [a1, a0] and
// its point at s has the angle arc_angle(arc_spans(a1, a0), a0 + a1 - s).
//
// Refuses (GeometryError "line segment" / "circle" / "ellipse"): t1 <= t0, non-positive or non-finite
// radii, equal angles, a sweep over 2 pi + 1e-9 (core/arc_parameterization).
#include <Eigen/Geometry>

#include "core/axis_frame.hpp"
#include "core/nurbs_curve.hpp"

namespace cadnurbs {

// Order 2, knots {t0, t0, t1, t1}, points {from, to}: the point at t is from + (t - t0)/(t1 - t0) (to - from).
NurbsCurve line_segment(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double t0, double t1);

// o + r (cos a x + sin a y) for a from a0 to a1: order 3, rational, dimension 3.
NurbsCurve circle_arc(const AxisFrame& frame, double radius, double a0, double a1);

// o + r1 cos a x + r2 sin a y for a from a0 to a1, the same parameterisation as circle_arc (a is the
// ellipse's parametric angle, not the polar angle of the point).
NurbsCurve ellipse_arc(const AxisFrame& frame, double semi_axis_1, double semi_axis_2, double a0, double a1);

// The circle in 2D (dimension 2, z = 0) for trimming curves: centre + r (cos a, sin a).
NurbsCurve circle_arc_2d(const Eigen::Vector2d& centre, double radius, double a0, double a1);

}  // namespace cadnurbs
