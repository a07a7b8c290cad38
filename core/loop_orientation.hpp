#pragma once
// Trimming-loop directions by the VRML/X3D rule, decided from the loops' geometry alone.
#include <vector>

#include "core/trimmed_surface.hpp"

namespace cadnurbs {

// Each loop lying inside an even number of the other loops (an outer boundary; a face may have several)
// is made counter-clockwise in (u, v), each inside an odd number (a hole) clockwise; a reversed loop also
// flips its TrimEdgeRef::reversed flags. Containment is a majority vote of sample points of the loop, so
// loops touching another at a vertex or along a seam are still classified right.
void orient_loops(std::vector<TrimLoop>& loops);

}  // namespace cadnurbs
