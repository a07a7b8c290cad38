#pragma once
// Our own STEP reader's scene against OpenCASCADE's reading of the same file (issue 37's checks): the same
// scene tree (names, source entities, placements), the same faces with the same surface types and
// colours, every trimmed face's area within `area_tolerance` (relative) of OCCT's face's (both by
// trimmed_surface_area to 1e-8),
// a certified tessellation at D = 0.01 x the diagonal within D of OCCT's exact faces (measure_deviation,
// two-sided) and watertight on every closed solid wherever OCCT's scene, meshed the same way, is.
// Failures are GoogleTest EXPECTs; one table row printed.
#include <string>

#include "formats/brep/brep_translation.hpp"

namespace cadnurbs::test {

void expect_same_as_occt(const BrepTranslation& native, const std::string& path, const std::string& label,
                         double area_tolerance = 1e-6);

}  // namespace cadnurbs::test
