#pragma once
// How far a lossy re-encoding of a scene (e.g. a .cnb read back) moved it: two scenes of the same
// structure (same node tree, shapes, loops, segments, knots; a trimming curve may have other knots over
// the same domain, as where the .cnb writer removed spare ones) compared point by point at the same
// parameters, in world coordinates:
//   surfaces   - both surfaces on a grid of the domain (samples_per_span per knot span in u and v,
//                at most 256 a direction, knot lines included);
//   boundaries - every trimming segment sampled at the same parameters (per span of the original's), each
//                mapped by its own surface; where the decoded segment is another curve (another order or
//                domain: the .cnb writer refits approximated pcurves), the two images both ways, each
//                sample to the nearest point of the other's image as a polyline of up to 256 points;
//   curves     - 3D curves sampled the same way; meshes - corresponding vertices.
// A measurement (attained distances at samples), not a bound.
#include "core/scene.hpp"

namespace cadnurbs {

struct PairedDeviation {
  double surfaces = 0, boundaries = 0, curves = 0, meshes = 0;
  long samples = 0;
  double max() const;
};

// Throws std::invalid_argument when the two scenes differ in structure (which node, shape or segment
// is named in the message).
PairedDeviation paired_scene_deviation(const Scene& original, const Scene& decoded, int samples_per_span = 4);

}  // namespace cadnurbs
