#pragma once
// Step 2 of tessellate_to_deviation, on every face but a curve's first: the curve's samples located on
// this face's own trim segment (internal).
//
// In: the face, its use of the curve (a segment whose curve was sampled on another face), the curve's
// samples, the nodes at the segment's start and end, and D. Out: the loop points of the segment, start
// included, end excluded (the end starts the next segment), appended to `out`; each carries the shared
// node's 3D point as it is (bit-identical vertices on both faces) and the (u,v) on this face where the
// segment comes nearest to it: Newton on the segment's 3D image from the arc-length-proportional
// parameter (project_to_trim_curve), then polished on the surface (project_to_surface) when that stays
// close. The parameters always advance, so two shared points never become one vertex here.
// Refuses (returns false, `out` untouched) when an end or a sample is farther than D from this face:
// the two faces disagree about the edge, and the caller samples the segment on its own.
#include <vector>

#include "analysis/tessellation/model_curves.hpp"
#include "analysis/tessellation/model_nodes.hpp"
#include "analysis/tessellation/tessellation_face.hpp"

namespace cadnurbs::tessellation {

bool invert_shared_samples(const Face& face, const CurveUse& use, const ModelCurve& curve, NodeId start_node,
                           NodeId end_node, const ModelNodes& nodes, double max_deviation, std::vector<LoopPoint>& out);

}  // namespace cadnurbs::tessellation
