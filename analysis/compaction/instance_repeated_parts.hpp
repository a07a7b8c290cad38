#pragma once
// Repeated parts found and placed as copies. Electronic parts repeat one shape many times inside one
// solid (the pins of a DIP or a connector, the balls of a BGA, the terminals of a QFN) and a STEP file
// spells out every copy; written once and placed by a transform, each copy costs a few bytes.
#include <functional>

#include "core/scene.hpp"

namespace cadnurbs {

// Splits the unnamed trimmed-surface shapes of every node into parts, a part being the faces of one
// colour joined by shared edges (TrimEdgeRef ids; a fused pin shares edges with its body). Where two or more parts are the same up to a rigid motion (faces in
// the same order with equal orders, knots, weights, trimming loops and colours, and every control point
// of one within `tolerance` of the moved control point of the other, the motion found by least squares),
// each becomes a child node: the first with the identity transform and its own shapes, every other one
// with the motion as its transform and an exact copy of the first's shapes, so that a writer finds equal
// content and writes it once. Parts that occur once stay where they were. Returns the number of copies
// placed (parts beyond the first of each kind).
int instance_repeated_parts(SceneNode& node, double tolerance);

// The same for single faces that no repeated part took: the unnamed trimmed surfaces for which
// `eligible` holds (a hole's wall in a plate, a fillet), each a part of one face.
int instance_repeated_faces(SceneNode& node, double tolerance, const std::function<bool(const Shape&)>& eligible);

}  // namespace cadnurbs
