#pragma once
// OCCT B-splines to the core NURBS model: knots expanded with their multiplicities into flat (VRML-style)
// knot vectors, control points in VRML order (u fastest), weights empty unless rational. Periodic
// B-splines are unperiodized and unclamped ends clamped, so every knot vector starts and ends with `order`
// equal knots (what viewers expect); geometry and parameters stay the same.
// Internal to formats/brep, step and iges: includes OCCT.
#include <Geom2d_BSplineCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>

#include "core/nurbs_curve.hpp"
#include "core/nurbs_surface.hpp"

namespace cadnurbs {

// The surface as a NurbsSurface (not validated; OCCT's own checks apply).
NurbsSurface to_nurbs_surface(const Handle(Geom_BSplineSurface)& surface);

// A 2D curve as a NurbsCurve of dimension 2 (z = 0).
NurbsCurve to_nurbs_curve_2d(const Handle(Geom2d_BSplineCurve)& curve);

}  // namespace cadnurbs
