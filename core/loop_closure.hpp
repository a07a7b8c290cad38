#pragma once
// Closing the small gaps a B-rep leaves between consecutive trim segments (pcurves meet their vertices
// only within the vertex tolerance).
#include "core/trimmed_surface.hpp"

namespace cadnurbs {

// Moves the end of `a` and the start of `b` to the midpoint between them: the end control point of a
// clamped NURBS (where a clamped curve ends), the end point of a polyline. The rest of each curve moves
// by less than the gap. Throws GeometryError("trim segment", ...) for a NURBS that is not clamped there.
void join_segments(TrimSegment& a, TrimSegment& b);

}  // namespace cadnurbs
