#pragma once
// Crease tags on the flat spans between corners of a Loop control mesh. Loop's edge rule puts the new
// point of a smooth edge at 3/8 of each end plus 1/8 of each opposite vertex: on a flat face whose
// outline turns inward (an L-shaped end face, a slot), with every vertex a corner, the edge from the
// inner corner gets its point outside the outline, in the face's own plane, and the limit surface
// covers part of the notch. No fit of the control points takes it back without moving the corners off
// the input's corners, and its samples hardly see it (the offset lies in the input's tangent plane).
// A crease edge splits at its midpoint instead, so a flat triangle whose three sides are creases and
// three corners fixed refines inside itself: its limit is the flat triangle.
// Corpus (issue 38 item 6): dm1-id-214.stp meshed by OpenCASCADE, at 200 control vertices the limit
// surface reached 2.46 mm into the notch of its L-shaped ends, against the quadric decimation's max of
// 2.35 mm.
#include <cmath>

#include "core/subdivision_control_mesh.hpp"

namespace cadnurbs {

// Takes a control mesh and a flatness angle in radians (>= 0); returns it with every interior edge
// (two faces) added to crease_edges whose two ends are corners (tagged, or with 3 or more sharp edges:
// crease-tagged, boundary or non-manifold) and whose two faces' normals differ by less than the angle.
// Positions, triangles and the tags already there are unchanged; an edge is tagged once. A face without
// area makes its edges not flat. Refuses (std::invalid_argument) a vertex index out of range or a
// negative angle.
SubdivisionControlMesh crease_flat_corner_spans(SubdivisionControlMesh mesh, double flat_angle_radians);

// The flatness the fit's starts are creased at (fit_best_start, fit_to_tolerance): 1 degree, far
// below any crease angle, and far above the rounding of a CAD kernel's flat face written as float STL.
inline constexpr double kFlatCornerSpanAngle = M_PI / 180;

}  // namespace cadnurbs
