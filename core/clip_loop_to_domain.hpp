#pragma once
// A trimming loop cut to the surface's domain, as GLU and the VRML/X3D viewers built on it draw loops that
// leave the domain: only the part of the region the loop encloses that lies in the domain is drawn.
// white_dune writes such loops (door.x3dv: a +-10 square about a 1 x 5 domain, a circle about a corner).
//
// In:  a closed loop (either orientation), the domain box [u0, u1] x [v0, v1], and how finely to look for
//      the loop's crossings of the box's sides (samples per knot span; each crossing then bisected to
//      round-off). An excursion between two samples is not seen: the caller's clamping handles those.
// Out: loops bounding (the region the loop encloses) within the box, each oriented as the input loop: the
//      loop's pieces inside the box (split exactly, split_curve) joined by polylines along the box's sides
//      in the loop's direction. Empty when the region misses the box; the box's boundary when the loop
//      runs round the whole box. The pieces lose their shared-edge references.
// Per loop, so that the even-odd region of several loops cut one by one is that of the loops, cut.
#include <vector>

#include "core/trimmed_surface.hpp"

namespace cadnurbs {

struct DomainBox {
  double u0, u1, v0, v1;
};

std::vector<TrimLoop> clip_loop_to_domain(const TrimLoop& loop, const DomainBox& box, int samples_per_span = 64);

}  // namespace cadnurbs
