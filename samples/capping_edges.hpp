#pragma once
// The capping's topology as a B-rep would state it, for watertight tessellation: the body gets a
// loop around its whole (u, v) domain whose v-end sides are the lids' edges and whose u sides are
// one seam edge; each lid's loop names its edge, running with or against the body's side.
#include "core/scene.hpp"

namespace cadnurbs {

// Takes a scene made by capping_nurbs (shapes body, lid-start, lid-end) and sets edge ids 1 (start
// lid), 2 (end lid) and 3 (the body's seam). The written files stay without these loops: this is
// for tessellating and measuring, where shared edges matter.
void share_capping_edges(Scene& capping);

}  // namespace cadnurbs
