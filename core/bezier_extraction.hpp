#pragma once
// Splitting a NURBS into its (rational) Bézier pieces by raising every interior knot to full
// multiplicity. Each piece is returned as a NURBS with a clamped knot vector over its own span.
#include <vector>

#include "core/nurbs_curve.hpp"
#include "core/nurbs_surface.hpp"

namespace cadnurbs {

// One curve per non-empty knot span, each with order control points.
std::vector<NurbsCurve> bezier_segments(const NurbsCurve& curve);

// Patches in u-fastest order over the non-empty spans, each with u_order x v_order control points.
std::vector<NurbsSurface> bezier_patches(const NurbsSurface& surface);

}  // namespace cadnurbs
