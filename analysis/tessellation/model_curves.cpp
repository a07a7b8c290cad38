#include "analysis/tessellation/model_curves.hpp"

namespace cadnurbs::tessellation {

CurveId ModelCurves::add(bool unnamed) {
  curves_.emplace_back();
  curves_.back().unnamed = unnamed;
  return CurveId{static_cast<int>(curves_.size()) - 1};
}

CurveId ModelCurves::of_edge(const Eigen::Affine3d& world, int edge) {
  auto [it, fresh] = curve_of_edge_.emplace(std::pair{placement_of(world), edge}, 0);
  if (fresh) it->second = add(false).index;
  return CurveId{it->second};
}

int ModelCurves::placement_of(const Eigen::Affine3d& world) {
  for (size_t i = 0; i < placements_.size(); ++i)
    if (placements_[i] == world.matrix()) return static_cast<int>(i);
  placements_.push_back(world.matrix());
  return static_cast<int>(placements_.size()) - 1;
}

}  // namespace cadnurbs::tessellation
