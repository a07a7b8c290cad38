#pragma once
// The parametrisation of one trimming segment (a 2D NURBS curve, or a polyline parametrised by its
// vertex index: vertex i at t = i, straight between), as every consumer of trimming loops walks it:
// tessellation, area, deviation measurement, point inversion.
#include <Eigen/Core>
#include <vector>

#include "core/trimmed_surface.hpp"

namespace cadnurbs {

// Parameter range of a segment: the curve's domain, or [0, points - 1] for a polyline.
double segment_t0(const TrimSegment& segment);
double segment_t1(const TrimSegment& segment);

// (u,v) at parameter t (clamped to the range), and its derivative d(u,v)/dt. A polyline's vertices
// come back bit for bit at whole t; its derivative is that of the piece starting at or before t.
Eigen::Vector2d segment_uv(const TrimSegment& segment, double t);
Eigen::Vector2d segment_tangent(const TrimSegment& segment, double t);

// Parameters where the segment may bend: distinct knots in the domain (ends included), or the
// polyline's vertices.
std::vector<double> segment_breaks(const TrimSegment& segment);

// Parameters where it may have a corner: its ends and the C0 knots between (c0_knots), or the
// polyline's vertices.
std::vector<double> segment_kinks(const TrimSegment& segment);

}  // namespace cadnurbs
