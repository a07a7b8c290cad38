#pragma once
// Length units by name (as STEP and IGES files, VRML WorldInfo lines and the command line's --units name
// them), and a scene re-expressed in another unit.
#include <optional>
#include <string>

#include "core/scene.hpp"

namespace cadnurbs {

// Takes a unit name as a STEP file (SI names with prefixes, "millimetre", "metre", or conversion-based
// names such as "INCH", "FOOT") or an IGES global section ("MM", "IN", "INCH", "FT", "M", "KM", "MIL",
// "UM", "CM", "UIN", "MI") gives it, in any case, or "dm", or "kicad" (0.1 inch, the unit KiCad's VRML
// reader assumes). Returns the unit with a short name ("mm", "cm", "dm", "m", "km", "um", "nm", "inch",
// "ft", "mil", "uin", "mi", "kicad") and its size in millimetres; nullopt for a name it does not know.
std::optional<LengthUnit> length_unit_named(const std::string& name);

// The scene with its lengths in `unit`: control points (Euclidean), mesh positions and transform
// translations scaled by scene.unit.millimetres / unit.millimetres; weights, knots, trimming curves
// (they live in (u,v)), normals and rotations unchanged; source_unit kept. Exact up to the rounding of
// one multiplication per coordinate.
Scene in_unit(Scene scene, const LengthUnit& unit);

}  // namespace cadnurbs
