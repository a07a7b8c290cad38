#pragma once
// A trimmed surface mirrored in u (u -> a + b - u over its domain [a, b]): the same points, Su reversed, so
// Su x Sv points the other way. B-rep readers use it for faces whose normal is against their surface's.
#include "core/trimmed_surface.hpp"

namespace cadnurbs {

// Mirrors the surface (control columns and u knots reversed) and its loops' points in u, exactly; the
// loops' directions flip with it (callers orient them again).
void mirror_in_u(TrimmedSurface& face);

}  // namespace cadnurbs
