#pragma once
// Closing the small gaps a B-rep leaves between consecutive trim segments (pcurves meet their vertices
// only within the vertex tolerance).
#include <string>
#include <vector>

#include "core/trimmed_surface.hpp"

namespace cadnurbs {

// Moves the end of `a` and the start of `b` to the midpoint between them: the end control point of a
// clamped NURBS (where a clamped curve ends), the end point of a polyline. The rest of each curve moves
// by less than the gap. Throws GeometryError("trim segment", ...) for a NURBS that is not clamped there.
void join_segments(TrimSegment& a, TrimSegment& b);

// Joins every pair of consecutive segments of `loop` (the last with the first) whose gap is at most
// `tolerance`, as join_segments does. A larger gap means the loop is not what the file says: throws
// GeometryError(loop_name, "does not close: gap G after trim N exceeds the tolerance T"), N being
// trim_numbers[i] for the gap after segment i (the file's own numbering).
void close_loop_gaps(TrimLoop& loop, double tolerance, const std::vector<int>& trim_numbers,
                     const std::string& loop_name);

}  // namespace cadnurbs
