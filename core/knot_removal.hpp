#pragma once
// Knot removal within a tolerance (Piegl & Tiller, The NURBS Book, 2nd ed., §5.4, after Tiller 1992).
// Curves that an exchange file or a CAD kernel made by approximation (pcurves projected onto a surface,
// intersection curves) carry far more knots than their shape needs: a trimming curve of 150 control
// points where 10 would do within a micrometre. Surfaces made by fitting or by refinement do the same.
//
// One removal. The knot-insertion equations P_k = a_k Q_k + (1 - a_k) Q_{k-1} are solved for the new
// points Q from both ends; where the two solutions meet they disagree by a vector δ (the removal's
// error E = |δ|). The kept net, with the knot inserted again, differs from the old net at one control
// point only, by at most δ, so the curve moves by δ times one basis function (at most 1): by at most E.
// Rational curves and surfaces are handled in homogeneous coordinates (w·P, w), with the points
// measured from the centre c of their bounding box (removal is linear in (w·(P - c), w), so the centre
// changes nothing but the bound). With δ = (δx, δw) the Euclidean curve moves by
//     |C' - C| = N(t) |δx - (C - c) δw| / W'(t)  <=  (|δx| + R |δw|) / w'_min  (<= E sqrt(1 + R^2) / w'_min),
// where R bounds |C - c| (the input's control points' largest distance from c, plus the tolerance, since
// the curve is a convex combination of its points and has moved by at most the tolerance so far) and
// w'_min is a lower bound of the weights after the removal (W' is a convex combination of them; the
// smallest of the input's weights and of every weight a removal made).
// Surfaces: a knot of u is removed from every row of the net at once (each row a curve in u; v the
// same with columns); the surface moves by sum_j N_j(v) (its row's move) <= the largest row bound.
// Removals that would make a weight non-positive are refused.
// Greedy: interior knots are tried from the left, one occurrence at a time (the last of equal values),
// pass after pass (surfaces alternate u and v), while the sum of the accepted removals' bounds stays
// within `tolerance`; by the triangle inequality the result lies within `tolerance` of the input at
// every parameter. Knots repeated more than the degree (a discontinuity) are kept.
// The result is then checked by sampling against the input at the same parameters (curves 8 points per
// input span; surfaces 4 per span and direction, at most 256 a direction); should any sample be off by
// more than `tolerance`, the input is returned unchanged. The parametrisation and domain never change,
// so trimming loops in (u,v) stay valid and their 3D images move by at most `tolerance` too.
#include "core/nurbs_curve.hpp"
#include "core/nurbs_surface.hpp"

namespace cadnurbs {

// The curve with knots removed as above; `tolerance` in the units of the curve's points. `removed`,
// when given, receives the number of knots removed. A non-positive tolerance returns the curve as it is.
NurbsCurve remove_knots(const NurbsCurve& curve, double tolerance, int* removed = nullptr);

// The surface with knots of u and v removed as above (tolerance in the units of its points; `removed`:
// knots removed in both directions together).
NurbsSurface remove_knots(const NurbsSurface& surface, double tolerance, int* removed = nullptr);

}  // namespace cadnurbs
