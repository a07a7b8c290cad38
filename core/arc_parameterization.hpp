#pragma once
// The rational quadratic circle arc and the exact map between its NURBS parameter and the angle.
// Sources: Piegl & Tiller, The NURBS Book, 2nd ed., §7.3 (circle as a rational quadratic Bézier arc:
// end points on the circle, the middle point where the end tangents meet, at distance 1/cos h from the
// centre, weight cos h for a sweep of 2h) and §7.5 (A7.1: whole arcs from spans of at most 90 degrees
// joined by double knots).
//
// The parameter is chosen so that it equals the angle at every knot: the arc [start, end] is cut into
// `spans` equal spans, and span k runs over the knot interval [start + k w, start + (k+1) w] (w the span
// sweep). Inside a span of sweep 2h centred on the angle c, the local Bézier parameter s in [0, 1] and
// the angle a satisfy tan((a - c)/2) = tan(h/2) (2 s - 1) (the rational quadratic circle is the
// stereographic, half-angle-tangent parameterisation, so tan((a - c)/2) is linear in s; at s = 0, 1/2, 1
// it gives c - h, c, c + h). Both directions are closed forms, so arc_parameter and arc_angle are exact
// inverses up to rounding, monotone, and exactly equal to the angle at every knot.
//
// In:  start and end angles in radians, 0 < end - start <= 2 pi (+ 1e-9 rounding).
// Out: ArcSpans{start, end, spans}: the fewest equal spans of at most pi/2 (1 to 4).
// Refuses (GeometryError "arc"): non-finite angles, end <= start, a sweep over 2 pi + 1e-9.
#include "core/nurbs_curve.hpp"

namespace cadnurbs {

struct ArcSpans {
  double start = 0, end = 0;  // angles in radians, 0 < end - start <= 2 pi (+ rounding)
  int spans = 1;
};

ArcSpans arc_spans(double start_angle, double end_angle);

// The knot at the k-th span end, k = 0 .. spans: start + k (end - start) / spans, and exactly end at
// k = spans. unit_arc's knots are these values.
double arc_knot(const ArcSpans& arc, int k);

// The NURBS parameter of an angle: the exact inverse of arc_angle, monotone, equal to the angle at
// every knot. Angles outside [start, end] are clamped to the nearer end (unwrap them first).
double arc_parameter(const ArcSpans& arc, double angle);

// The angle at a NURBS parameter (clamped to [start, end] likewise).
double arc_angle(const ArcSpans& arc, double parameter);

// The unit circle's arc as a rational quadratic: order 3, 2 spans + 1 points, dimension 2 (z = 0),
// weights 1, cos h, 1 per span, knots {start x3, each inner span end x2, end x3}. Its point at
// parameter s is exactly (cos a, sin a), a = arc_angle(arc, s). A full circle (sweep 2 pi within 1e-12)
// ends on its first point bit for bit.
NurbsCurve unit_arc(const ArcSpans& arc);

}  // namespace cadnurbs
