#pragma once
// The model curves of a tessellation (internal; see CurveId): which trim segments of which faces are
// one curve, and the samples each curve carries once it is sampled (step 2 of tessellate_to_deviation).
// A curve is sampled on its first use's face; every other use locates the same 3D points on its own
// face, so all faces put bit-identical vertices along it.
#include <Eigen/Geometry>
#include <map>
#include <utility>
#include <vector>

#include "analysis/tessellation/tessellation_ids.hpp"

namespace cadnurbs::tessellation {

inline CurveEndSide opposite(CurveEndSide side) {
  return side == CurveEndSide::start ? CurveEndSide::end : CurveEndSide::start;
}

// Segment `segment` of loop `loop` of face `face`, lying on model curve `curve`; `reversed`: the
// segment runs against the curve's direction.
struct CurveUse {
  int face, loop, segment;
  CurveId curve;
  bool reversed;

  // The curve end at the segment's start (or end).
  CurveEnd end(CurveEndSide of_segment) const { return {curve, reversed ? opposite(of_segment) : of_segment}; }
};

struct ModelCurve {
  std::vector<CurveUse> uses;  // the first is the face it is sampled on (its origin)
  bool degenerate = false;     // collapsed to one point in 3D: one node, never sampled
  bool unnamed = false;        // a trim segment of no B-rep edge (a gap closure formats/brep added)
  // Samples, in curve direction, ends included (set by sampling, extended by span splits):
  std::vector<Eigen::Vector3d> points;  // in the origin face's frame
  std::vector<Eigen::Vector2d> uvs;     // on the origin face
  std::vector<NodeId> nodes;
  std::vector<double> ts;   // parameters on the origin segment
  std::vector<double> arc;  // cumulative chord length, as a fraction of the whole
};

class ModelCurves {
 public:
  // A curve that no other segment shares.
  CurveId add(bool unnamed);

  // The curve of B-rep edge `edge` of a solid placed by `world`, made on first request. An edge id
  // names one edge of one solid; a solid placed several times (assembly instances) has one curve per
  // edge and distinct world transform.
  CurveId of_edge(const Eigen::Affine3d& world, int edge);

  ModelCurve& operator[](CurveId c) { return curves_[c.index]; }
  const ModelCurve& operator[](CurveId c) const { return curves_[c.index]; }
  int size() const { return static_cast<int>(curves_.size()); }

 private:
  std::vector<ModelCurve> curves_;
  std::map<std::pair<int, int>, int> curve_of_edge_;  // (placement, edge) -> curve index
  std::vector<Eigen::Matrix4d> placements_;
  int placement_of(const Eigen::Affine3d& world);
};

}  // namespace cadnurbs::tessellation
