#pragma once
// One face on its way through tessellate_to_deviation (internal): what each step of
// tessellate_to_deviation.hpp fills in and the next reads.
//   preparation:                trimmed, name, world, eval, bound, loops, curve, reversed
//   step 1 (grid_planning):     us, vs
//   step 2 (shared_edges):      points (refilled while chords are split)
//   steps 3-5 (face_meshing):   mesh
#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "analysis/eval/surface_deviation_bound.hpp"
#include "analysis/eval/surface_evaluator.hpp"
#include "analysis/tessellation/tessellation_ids.hpp"
#include "core/triangle_mesh.hpp"
#include "core/trimmed_surface.hpp"

namespace cadnurbs::tessellation {

// One point of a face's loop, in loop order.
struct LoopPoint {
  Eigen::Vector2d uv;
  Eigen::Vector3d point;  // the mesh vertex, in the face's frame (a shared node's point, as it is)
  NodeId node;            // points with the same node are one mesh vertex
  // Set when the loop runs from here to the next point along this collapsed segment (a pole: all its
  // points are this one 3D point), between its parameters t and t_next.
  const TrimSegment* degenerate = nullptr;
  double t = 0, t_next = 0;
  // The chord from here to the next point as a span of a model curve; empty when it cannot be split
  // (a collapsed segment, or samples of this face's own).
  std::optional<CurveSpan> chord = std::nullopt;
};

struct Face {
  const TrimmedSurface* trimmed = nullptr;
  std::string name;
  Eigen::Affine3d world = Eigen::Affine3d::Identity();
  std::unique_ptr<SurfaceEvaluator> eval;
  SurfaceDeviationBound bound;
  std::vector<TrimLoop> loops;                 // the face's loops (a rectangle when untrimmed)
  std::vector<std::vector<CurveId>> curve;     // model curve per segment
  std::vector<std::vector<bool>> reversed;     // segment runs against its curve
  std::vector<std::vector<LoopPoint>> points;  // filled by sharing, consumed by meshing
  std::vector<double> us, vs;                  // the tensor grid (plan_tessellation_grid)
  TriangleMesh mesh;
};

}  // namespace cadnurbs::tessellation
