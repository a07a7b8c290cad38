#pragma once
// The surface points one face's meshing asks for, each evaluated once (internal).
//
// In: the face's SurfaceEvaluator. Out: point(u, v), bit for bit SurfaceEvaluator::point(u, v). Meshing
// asks for many points again: a grid or refinement point when it is inserted, when the triangulation
// describes it and when its error is taken; a lattice point on a side shared by two triangles, or kept
// from one lattice (k = 3) to the next (k = 6); a peak that becomes a vertex. The first call evaluates,
// later calls with the same bits return the stored point. Keys are the parameters' bit patterns, so no
// two different (u, v) (not even -0 and +0) can share a point and the mesh is the one without the cache.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "analysis/eval/surface_evaluator.hpp"

namespace cadnurbs::tessellation {

class SurfacePointCache {
 public:
  // expected: about how many distinct points will be asked for (the table grows beyond).
  SurfacePointCache(const SurfaceEvaluator& surface, std::size_t expected);

  Eigen::Vector3d point(double u, double v);

 private:
  struct Entry {
    std::uint64_t u, v;
    Eigen::Vector3d point;
  };
  const SurfaceEvaluator& surface_;
  std::vector<Entry> entries_;        // in the order of first request
  std::vector<std::uint32_t> slots_;  // 1 + entry index, 0 when free: open addressing, linear probing,
                                      // a power of two at least twice the entries

  void grow();
};

}  // namespace cadnurbs::tessellation
