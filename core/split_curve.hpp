#pragma once
// A NURBS curve cut in two at a parameter, exactly: the knot is inserted until the curve passes
// through a control point there (Boehm, Piegl & Tiller A5.1), and the control polygon is divided at it.
//
// In:  a valid curve (2D or 3D, rational or not) and t strictly inside its domain.
// Out: {before, after}: `before` runs over [domain start, t], `after` over [t, domain end], with the
//      curve's own parametrisation; before's end point and after's start point are one control point.
// Refuses (GeometryError "split curve") a t outside the open domain.
#include <utility>

#include "core/nurbs_curve.hpp"

namespace cadnurbs {

std::pair<NurbsCurve, NurbsCurve> split_curve(const NurbsCurve& curve, double t);

}  // namespace cadnurbs
