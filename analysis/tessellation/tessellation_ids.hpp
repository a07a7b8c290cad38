#pragma once
// Typed ids of the model geometry that tessellate_to_deviation shares between faces (internal to the
// files of analysis/tessellation/). An id is an index into the table that made it; the types keep a
// node from being passed where a curve, or a curve end, is meant.
#include <compare>

namespace cadnurbs::tessellation {

// A model vertex: a class of curve ends (a B-rep vertex), or a sample inside a model curve. Every face
// that uses a node puts the same 3D point there, bit for bit, and the points of one face with the same
// node become one mesh vertex (ModelNodes holds the points).
struct NodeId {
  int index = 0;
  auto operator<=>(const NodeId&) const = default;
};

// A model curve: one shared edge of the scene in one placement, or a trim segment of its own (ModelCurves
// holds them).
struct CurveId {
  int index = 0;
  auto operator<=>(const CurveId&) const = default;
};

// One end of a model curve, in the curve's own direction.
enum class CurveEndSide { start, end };

struct CurveEnd {
  CurveId curve;
  CurveEndSide side;
};

// The chord between samples `span` and `span + 1` of a model curve (in curve direction): what a split
// (ModelCurves::split_span) refines, on every face that uses the curve at once. Ordered by curve, then
// span, so that splitting in descending order leaves the spans still to split where they were.
struct CurveSpan {
  CurveId curve;
  int span = 0;
  auto operator<=>(const CurveSpan&) const = default;
};

}  // namespace cadnurbs::tessellation
