#pragma once
// Knot removal within a tolerance (Piegl & Tiller, The NURBS Book, 2nd ed., §5.4, after Tiller 1992).
// Curves that an exchange file or a CAD kernel made by approximation (pcurves projected onto a surface,
// intersection curves) carry far more knots than their shape needs: a trimming curve of 150 control
// points where 10 would do within a micrometre.
#include "core/nurbs_curve.hpp"

namespace cadnurbs {

// The curve with interior knots removed, one occurrence at a time, greedily from the left and pass
// after pass, while the sum of the removals' errors stays within `tolerance` (model units of the curve's
// points). Each removal solves the knot-insertion equations for the new control points from both ends;
// its error is the mismatch where the two solutions meet, which bounds how far the curve moves (the
// removed difference is multiplied by one basis function, at most 1). The result is then checked by
// sampling against the input (8 points per input span); should it be off by more than `tolerance`, the
// input is returned unchanged. Rational curves are returned unchanged (their bound needs the weights'
// range; not needed yet). `removed`, when given, receives the number of knots removed.
NurbsCurve remove_knots(const NurbsCurve& curve, double tolerance, int* removed = nullptr);

}  // namespace cadnurbs
