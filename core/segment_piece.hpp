#pragma once
// Pieces of trimming segments, for the repairs that cut loops (loop_self_crossing, clip_loop_to_domain).
#include <Eigen/Core>

#include "core/trimmed_surface.hpp"

namespace cadnurbs {

// The part of a segment over [t0, t1] (within its range; t0 < t1), in the segment's own parametrisation:
// a NURBS curve split exactly (split_curve); a polyline's vertices between, and its points at t0 and t1.
TrimSegment segment_piece(const TrimSegment& segment, double t0, double t1);

// Moves the segment's first (last) defining point to p: its start (end) for a clamped curve or polyline.
void set_segment_start(TrimSegment& segment, const Eigen::Vector2d& p);
void set_segment_end(TrimSegment& segment, const Eigen::Vector2d& p);

}  // namespace cadnurbs
