#pragma once
// How far apart two polynomial curves on the same domain can be at equal parameters: a bound, not a sample.
//
// Each curve gets the other's breakpoints as knots (knot insertion leaves a curve as it was), so on every
// span between breakpoints both are single polynomials. There they are written as Bézier pieces, raised to
// the larger degree, and subtracted; the difference lies in the convex hull of its Bernstein coefficients
// (Farin, "Curves and Surfaces for CAGD", ch. 5), so the largest coefficient's length bounds |a(t) - b(t)|
// on the span. The largest over the spans bounds it over the domain. The bound may exceed the true
// largest distance, never fall below it (up to rounding in double, some 1e-15 of the coordinates).
// A parametric distance bounds the Hausdorff distance between the two curves too.
#include <vector>

#include "core/nurbs_curve.hpp"

namespace cadnurbs {

// max over t of |a(t) - b(t)|, bounded as above. Refuses (std::invalid_argument) rational curves, and curves
// whose dimensions or domains differ.
double curve_distance_bound(const NurbsCurve& a, const NurbsCurve& b);

// The same bound span by span: one entry per span between consecutive breakpoints of either curve, in
// order, each bounding |a(t) - b(t)| for t in [start, end]. Refuses what curve_distance_bound refuses.
struct SpanDistance {
  double start = 0, end = 0, bound = 0;
};
std::vector<SpanDistance> curve_distance_bounds(const NurbsCurve& a, const NurbsCurve& b);

}  // namespace cadnurbs
