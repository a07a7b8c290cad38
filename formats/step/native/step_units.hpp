#pragma once
// The length and plane-angle units of a STEP representation context (GLOBAL_UNIT_ASSIGNED_CONTEXT): SI
// units with their prefixes, conversion-based units (INCH, DEGREE, ...) through their factors.
#include <string>

#include "formats/step/native/step_context.hpp"

namespace cadnurbs::step {

struct StepUnits {
  std::string length_name = "millimetre";  // SI: prefix + "metre"; conversion-based: the file's name (INCH)
  double millimetres = 1.0;                 // one length unit in millimetres
  double radians = 1.0;                     // one plane-angle unit in radians
};

// Takes a representation context (any entity; one without GLOBAL_UNIT_ASSIGNED_CONTEXT gives the defaults,
// millimetres and radians). Refuses (OutsideNativeSubset) a unit it cannot size: an unknown SI prefix, a
// conversion factor that is not a positive number, or conversions nested deeper than 4.
StepUnits read_units(const StepContext& context, EntityId representation_context);

}  // namespace cadnurbs::step
