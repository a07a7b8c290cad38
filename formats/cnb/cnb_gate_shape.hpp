#pragma once
// The shape of a traversal-coded mesh's border after the gate (docs/cnb.md, "Traversal-coded triangle
// mesh", version 9 on): a context for the symbol after a new vertex that writer and reader both compute
// from the points decoded so far. The far triangle closes on the border edge after the gate (R) only where
// the border turns towards it there; where the region is a planar face cut into triangles, a sharp turn
// all but forces the closing and a wide one all but rules it out.
//
// The candidate is w, the far end of the border edge after the gate from -> to; the corner is `to`. The
// shape is
//   0  no candidate (a border list of fewer than two edges), a zero-length gate or edge, or w not on the
//      far side of the gate's line from the apex (within the plane of the gate's triangle);
//   1  on the far side, but the triangle (to, from, w) not within about 8 degrees of the plane of the
//      gate's triangle (|cos| of their normals at most 0.99);
//   2, 3, 4  on the far side and in the plane, the border turning at `to` by an angle of at least 120
//      degrees, at least 60, less than 60.
//
// Measured on the traversals of 57 DFN/QFN KiCad parts at 0.01 mm (every 4th of the family), coded as
// version 9 writes them: the symbols cost 5,519 bytes in these contexts and 5,982 in the one context after
// a new vertex. After any other symbol the shape did not pay (the border closing on the edge before the
// gate is impossible right after a new vertex, and after the other symbols splitting the models cost more
// than it told): in 25 shapes (after and before) after every symbol, 6,511.
//
// Everything is evaluated in double from the grid points with +, - and * in the order written here (the
// file is compiled without fused multiply-add) and compared, never rounded: every reader computes the
// writer's shape.
#include <optional>

#include "formats/cnb/cnb_vertex_values.hpp"

namespace cadnurbs::cnb {

constexpr int gate_shape_count = 5;

// The shape after gate from -> to with apex `apex`; `after` is the far end of the border edge after the
// gate, where the gate's list has another edge.
int gate_shape(const GridPoint& from, const GridPoint& to, const GridPoint& apex, const std::optional<GridPoint>& after);

}  // namespace cadnurbs::cnb
