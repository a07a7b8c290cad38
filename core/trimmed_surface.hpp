#pragma once
// A NURBS surface with trimming loops in its (u,v) domain. VRML/X3D rule: the outer loop runs
// counter-clockwise, holes clockwise. No loops means the whole domain is kept.
#include <Eigen/Geometry>
#include <string>
#include <variant>
#include <vector>

#include "core/nurbs_curve.hpp"
#include "core/nurbs_surface.hpp"

namespace cadnurbs {

struct Polyline2D {
  std::vector<Eigen::Vector2d> points;  // at least two
};

// One piece of a loop: a 2D NURBS curve (dimension 2) or a polyline.
using TrimSegment = std::variant<NurbsCurve, Polyline2D>;

// Which model edge a trim segment lies on, so that faces sharing an edge can be tessellated with the
// same points there (a watertight mesh). `reversed`: the segment runs against the edge's direction.
struct TrimEdgeRef {
  int edge = -1;  // scene-wide edge number; -1: not shared with anything
  bool reversed = false;
  bool operator==(const TrimEdgeRef&) const = default;
};

struct TrimLoop {
  std::vector<TrimSegment> segments;  // each ends where the next starts; the last ends at the first's start
  std::vector<TrimEdgeRef> edges;     // empty, or one per segment
};

struct TrimmedSurface {
  NurbsSurface surface;
  std::vector<TrimLoop> loops;  // empty: untrimmed
};

Eigen::Vector2d segment_start(const TrimSegment& segment);
Eigen::Vector2d segment_end(const TrimSegment& segment);

// Largest distance between the end of a segment and the start of the next (closing segment included).
double loop_closure_gap(const TrimLoop& loop);

// The loop sampled as a closed polygon (last point != first); each NURBS piece with `samples_per_span`
// points per knot span, polylines as they are.
std::vector<Eigen::Vector2d> loop_polygon(const TrimLoop& loop, int samples_per_span = 16);

// Signed area of the sampled loop: positive when counter-clockwise.
double loop_signed_area(const TrimLoop& loop);

// The same loop traversed the other way.
TrimLoop reversed(const TrimLoop& loop);

// The loop of the whole domain, counter-clockwise: sides (v0 side, u1 side, v1 side, u0 side), each a
// two-point polyline; what an untrimmed surface is trimmed by.
TrimLoop domain_loop(const NurbsSurface& surface);

// Throws GeometryError unless the surface is valid and every loop has segments, valid 2D curves,
// and closes within `closure_tolerance` (in parameter units).
void validate(const TrimmedSurface& trimmed, const std::string& entity, double closure_tolerance = 1e-9);

}  // namespace cadnurbs
