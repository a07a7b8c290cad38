#pragma once
// The surface points one face's meshing asks for, each evaluated once (internal).
//
// In: the face's SurfaceEvaluator. Out: point(u, v), bit for bit SurfaceEvaluator::point(u, v). Meshing
// asks for many points again, mostly soon after: a grid or refinement point when it is inserted, when the
// triangulation describes it and when its error is taken; a lattice point kept from one lattice (k = 3)
// to the next (k = 6, 12); a lattice point on a side shared by two triangles; a peak that becomes a
// vertex. A direct-mapped table (a slot per hash, the newest point wins) keeps the recent points: it
// stays within the processor's cache, where a table of every point of a large face would miss it on
// most look-ups and cost more than it saves. Keys are the parameters' bit patterns, so no two different
// (u, v) (not even -0 and +0) can share a point and the mesh is the one without the cache.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "analysis/eval/surface_evaluator.hpp"

namespace cadnurbs::tessellation {

class SurfacePointCache {
 public:
  // expected: about how many distinct points will be asked for (sizes the table, up to a limit).
  SurfacePointCache(const SurfaceEvaluator& surface, std::size_t expected);

  Eigen::Vector3d point(double u, double v);

 private:
  struct Slot {
    std::uint64_t u = 0, v = 0;
    Eigen::Vector3d point;
    bool used = false;
  };
  const SurfaceEvaluator& surface_;
  std::vector<Slot> slots_;  // a power of two
};

}  // namespace cadnurbs::tessellation
