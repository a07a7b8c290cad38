#pragma once
// Knot insertion and refinement (Boehm; Piegl & Tiller A5.1, A5.3, A5.4). The shape never changes.
#include "core/nurbs_curve.hpp"
#include "core/nurbs_surface.hpp"

namespace cadnurbs {

enum class SurfaceDirection { u, v };

// Inserts t `times` times. Refuses t outside the domain or a resulting multiplicity above the
// degree (order - 1), the most that keeps the curve in one piece.
NurbsCurve insert_knot(const NurbsCurve& curve, double t, int times = 1);
NurbsSurface insert_knot(const NurbsSurface& surface, SurfaceDirection direction, double t, int times = 1);

// Inserts every value of `new_knots` (non-decreasing, inside the domain) at once, in time linear in the
// control points. Refuses what insert_knot refuses.
NurbsCurve refine_knots(const NurbsCurve& curve, const std::vector<double>& new_knots);
NurbsSurface refine_knots(const NurbsSurface& surface, SurfaceDirection direction,
                          const std::vector<double>& new_knots);

}  // namespace cadnurbs
