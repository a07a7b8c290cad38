#pragma once
// A Brep loop's trims, in the file's order, made one closed loop that follows the VRML/X3D rule in the surface's own
// (u, v): outer loops counter-clockwise, holes clockwise. Rhino's loops already do (see docs/3dm.md); the loop's type
// decides, the sampled signed area only says which way the file's loop runs.
//
// In:  the trims as segments (each with its edge reference), the loop's role, the gap the trims may leave between
//      consecutive ends (their own tolerance), the file's trim numbers (for messages) and the loop's name
//      ("face 3 loop 2").
// Out: the gaps closed by moving the ends to their midpoint (close_loop_gaps), the loop reversed when its role asks
//      for it (a slit or an unknown role keeps its direction).
// Refuses (GeometryError, from close_loop_gaps) a gap larger than the tolerance: the loop is not what the file says.
#include <string>
#include <vector>

#include "core/trimmed_surface.hpp"

namespace cadnurbs::rhino {

enum class LoopRole { outer, inner, other };

TrimLoop oriented_loop(TrimLoop loop, LoopRole role, double tolerance, const std::vector<int>& trim_numbers,
                       const std::string& loop_name);

}  // namespace cadnurbs::rhino
