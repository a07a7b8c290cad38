#pragma once
// The core NURBS model to OCCT B-splines: flat knot vectors split into distinct knots and multiplicities,
// control points from VRML order (u fastest) into OCCT's (u row, v column) grid.
// Internal to formats/brep, step and iges: includes OCCT.
#include <Geom2d_BSplineCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>

#include "core/nurbs_curve.hpp"
#include "core/nurbs_surface.hpp"
#include "core/trimmed_surface.hpp"

namespace cadnurbs {

// Throws GeometryError(entity, reason) for invalid input (core's validate) and for what OCCT cannot hold:
// an interior knot repeated `order` times (a discontinuous B-spline).
Handle(Geom_BSplineSurface) to_occt_surface(const NurbsSurface& surface, const std::string& entity);

// A 3D NurbsCurve as a Geom_BSplineCurve; same refusals.
Handle(Geom_BSplineCurve) to_occt_curve(const NurbsCurve& curve, const std::string& entity);

// A trim segment (2D NurbsCurve, or polyline as a degree-1 B-spline with one span per piece, parameter =
// cumulative chord length) as a Geom2d_BSplineCurve; same refusals.
Handle(Geom2d_BSplineCurve) to_occt_curve_2d(const TrimSegment& segment, const std::string& entity);

}  // namespace cadnurbs
