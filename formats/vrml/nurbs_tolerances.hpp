#pragma once
// How precisely the numbers of one NURBS entity are written so that the evaluated geometry moves by at
// most a coordinate tolerance τ (absolute, model units, per coordinate). The rules, with w_min/w_max the
// extreme weights (1 for polynomial entities), D the largest coordinate extent of the control points,
// M the largest |coordinate| of a control point, Δ the shortest non-empty knot span, k the order:
//
//   Euclidean control points P:   τ/2        a rational basis is a partition of unity of non-negative
//                                            functions, so the curve moves no more than its points.
//   homogeneous control points wP: τ/2·w_min  S = Σ N_i (wP)_i / Σ N_i w_i moves by at most δ/w_min.
//   weights (Euclidean):          τ/4·w_min/D     ∂S/∂w_i = R_i (P_i - S)/w_i and |P_i - S| <= D.
//   weights (homogeneous):        τ/4·w_min/M     ∂S/∂w_i = -R_i S / w_i and |S| <= M.
//   knots:                        τ/4·Δ/(k·D·w_max/w_min), first-order estimate of a knot's pull on the
//                                 basis; never more than Δ/1000 so that spans keep their proportions.
//
// Weights are never written less precisely than w_min/100. Trimming curves live in the surface's (u,v)
// domain: they get a parameter tolerance τ/(10·L) (trim_parameter_tolerance, core/nurbs_surface.hpp), L
// the derivative bound there, and then the same rules.
#include "core/nurbs_curve.hpp"
#include "core/nurbs_surface.hpp"  // surface_derivative_bound, trim_parameter_tolerance

namespace cadnurbs {

// Absolute tolerances for the written numbers of one entity.
struct NurbsTolerances {
  double control_point = 0.0;  // each coordinate of P (Euclidean) or of w·P (homogeneous)
  double weight = 0.0;
  double knot = 0.0;
};

// For a surface or curve (2D curves in parameter units) and a coordinate tolerance τ > 0.
NurbsTolerances surface_tolerances(const NurbsSurface& surface, double coordinate_tolerance, bool homogeneous);
NurbsTolerances curve_tolerances(const NurbsCurve& curve, double coordinate_tolerance, bool homogeneous);

// The derivative bound L and trim_parameter_tolerance live in core/nurbs_surface.hpp.

}  // namespace cadnurbs
