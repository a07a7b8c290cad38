#pragma once
// Straight trimming segments written as polylines. Most trimming curves of real parts are straight
// lines in (u,v) (every edge of a planar face, the rulings of cylinders), and a CAD exchange file
// spells each as a NURBS curve with its own knots; a run of them is one polyline, exactly.
#include <optional>
#include <vector>

#include "core/trimmed_surface.hpp"

namespace cadnurbs {

// The vertices of `segment` when it is straight in (u,v) within `tolerance`: a polyline (its points), an
// order-2 curve (its control points, whatever its knots and weights: it runs straight between them),
// or a curve of higher order whose control points all lie within `tolerance` of the chord between its
// ends and project onto it in order (the curve lies in their convex hull and cannot turn back): its two
// ends. Nothing otherwise.
std::optional<std::vector<Eigen::Vector2d>> straight_segment_points(const TrimSegment& segment, double tolerance);

// `points` without the interior points that lie within `tolerance` of the line between the points kept on
// either side (the ends are kept). Greedy from the first point.
std::vector<Eigen::Vector2d> without_collinear_points(const std::vector<Eigen::Vector2d>& points, double tolerance);

// The loop with every run of consecutive straight segments as one Polyline2D without collinear points
// (a loop that is straight all round becomes one closed polyline). The loop is rotated to start at a
// curved segment when it has one, so no run is cut at the loop's start. Edge references of joined
// segments become -1 (not shared): they are only needed for tessellation, which reads the source.
// `runs`, when given, is increased by the number of polylines made from two or more segments.
TrimLoop join_straight_trim_runs(const TrimLoop& loop, double tolerance, int* runs = nullptr);

}  // namespace cadnurbs
