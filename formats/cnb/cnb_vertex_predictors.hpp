#pragma once
// Where a traversal-coded mesh's new vertex is predicted (docs/cnb.md, "Traversal-coded triangle mesh",
// version 8 on): beyond the gate from->to, whose triangle's third corner is apex, the writer picks one of
// four predictions per vertex and names it in a symbol.
//
//   0 parallelogram: from + to - apex. Exact across the strips of a cylinder or an extrusion.
//   1 arc after: the border's polyline c2 -> c1 -> to (the two border edges after the gate, read
//     backwards) continued by one more step of the same length, turned as it turned at c1. Exact, up to
//     rounding, on the polygon of a circle or of any arc of constant step, which CAD tessellations put on
//     the border of a planar face's fan, where the parallelogram misses by a chord.
//   2 arc before: the same along the two border edges before the gate, continued past from.
//   3 mirror: the apex reflected across the gate's line. Exact on a fan about a centre.
//
// Measured over the files cnb_coding writes for DFN-12-1EP 4x4mm at 0.01 mm: the best of the four for each
// vertex costs 28% fewer estimated bits than the parallelogram alone, the arcs winning 49% of the vertices;
// with the predictor's symbol, the file is 582 bytes against 617.
//
// The arc is the previous step d0 = to - c1 turned by the angle from d1 = c1 - c2 to d0:
// (2 (d1.d0) d0 - |d0|^2 d1) / (|d1| |d0|), which needs no trigonometry. Each prediction is evaluated in
// double in the order written here with +, -, *, / and one sqrt (all correctly rounded in IEEE 754; the
// file is compiled without fused multiply-add), then rounded to the nearest grid point, half away from
// zero: so every reader computes the same grid point the writer did. A missing chain (a border list of
// fewer than three edges), a zero-length edge or a gate of length 0 falls back to the parallelogram.
#include <array>
#include <optional>

#include "formats/cnb/cnb_vertex_values.hpp"

namespace cadnurbs::cnb {

constexpr int vertex_predictor_count = 4;

// The far vertex of the gate's triangle (from, to, apex) by the parallelogram.
GridPoint parallelogram(const GridPoint& from, const GridPoint& to, const GridPoint& apex);

// The step after c2 -> c1 -> c0, of the length of c1 -> c0, turned as c2 -> c1 -> c0 turned. Straight on
// when either step has length 0.
GridPoint arc_continuation(const GridPoint& c0, const GridPoint& c1, const GridPoint& c2);

// `apex` reflected across the line through from and to; the parallelogram when from == to.
GridPoint mirrored_apex(const GridPoint& from, const GridPoint& to, const GridPoint& apex);

// The border's polyline next to the gate: the two points before c0 (to or from) along it.
struct BorderChain {
  GridPoint c1, c2;
};

// The four predictions, by predictor number; an absent chain gives the parallelogram in its place.
std::array<GridPoint, vertex_predictor_count> vertex_predictions(const GridPoint& from, const GridPoint& to,
                                                                 const GridPoint& apex,
                                                                 const std::optional<BorderChain>& after_to,
                                                                 const std::optional<BorderChain>& before_from);

}  // namespace cadnurbs::cnb
