#pragma once
// A polynomial curve written again as a cubic B-spline with fewer control points, within a bound on the
// distance between the two curves' images.
//
// Pcurves that a kernel approximated carry far more control points than their shape needs, often at a
// high degree (the DTMB bow's boundary: degree 8, 313 control points in 40 spans, each span ending on a
// float64 knot, its speed from 1.8 to 40 along the curve). Knot removal (core/knot_removal) keeps the
// parametrisation, and so every span. A trimming curve's parametrisation means nothing to its face, so
// here it is given up:
// - The curve is reparametrised by arc length, piecewise: each span's parameter interval is mapped
//   linearly onto an interval in proportion to the length of its image. The result R is the same curve
//   (the same Bézier pieces, the knots moved), with its speed nearly even along it.
// - R is fitted by least squares (Piegl & Tiller §9.4.1, both end points fixed) with a cubic F, from one
//   span: curve_distance_bounds bounds |F(s) - R(s)| span by span, every span of F whose bound exceeds
//   the tolerance is halved, and F is fitted again, until every span passes (the bow's boundary within
//   3e-4 of its (u,v): 54 control points). Both R's own parameter, mapped onto [0, 1] as a whole, and the
//   arc-length one are tried; the fewer points win.
// Every point of F is then within `tolerance` of a point of the curve and the other way round (the two
// images are within that Hausdorff distance), and F starts and ends exactly where the curve does, so a
// loop stays closed. Its knots are whole numbers from 0 to a power of two (the halvings scaled up), which
// a .cnb writes as small numbers, a byte or two each.
#include <optional>

#include "core/nurbs_curve.hpp"

namespace cadnurbs {

// F as above, with fewer control points than `curve`; nullopt where no such F is within `tolerance` (in
// the units of the curve's points), or where `curve` is rational, has at most 4 control points, an image
// of no length, or tolerance <= 0.
std::optional<NurbsCurve> refit_cubic_within(const NurbsCurve& curve, double tolerance);

}  // namespace cadnurbs
