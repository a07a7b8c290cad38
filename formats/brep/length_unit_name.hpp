#pragma once
// Length units as STEP and IGES files name them. No OCCT types.
#include <optional>
#include <string>

#include "core/scene.hpp"

namespace cadnurbs {

// Takes a unit name as a STEP file (SI names with prefixes, "millimetre", "metre", or conversion-based
// names such as "INCH", "FOOT") or an IGES global section ("MM", "IN", "INCH", "FT", "M", "KM", "MIL",
// "UM", "CM", "UIN", "MI") gives it, in any case. Returns the unit with a short name ("mm", "cm", "m",
// "km", "um", "nm", "inch", "ft", "mil", "uin", "mi") and its size in millimetres; nullopt for a name it
// does not know.
std::optional<LengthUnit> length_unit_named(const std::string& name);

}  // namespace cadnurbs
