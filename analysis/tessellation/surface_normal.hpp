#pragma once
// Normals of a surface for tessellation (internal): whether Su x Sv is usable, and a unit normal even
// at a pole, where it is not.
#include <Eigen/Core>

#include "analysis/eval/surface_evaluator.hpp"

namespace cadnurbs::tessellation {

// Su x Sv is a usable normal: not zero, and not the cross product of a round-off Su (or Sv) at a
// pole, which a test relative to |Su| |Sv| would accept.
bool has_normal(const SurfaceJet& j);

// The unit normal (Su x Sv) at uv; where the surface has none there (a pole), the normal a little
// inside the domain (1e-7, 1e-5, then 1e-3 of it, stepping towards the middle); zero if none is found.
Eigen::Vector3d normal_at(const SurfaceEvaluator& e, const Eigen::Vector2d& uv);

}  // namespace cadnurbs::tessellation
