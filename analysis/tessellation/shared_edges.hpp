#pragma once
// Step 2 of tessellate_to_deviation (see its header): the trimming loops of all faces sampled so that
// edges shared by several faces carry the same vertices on each (internal).
//
// In: the faces, prepared (loops, evaluator, bound) and with their grids (step 1). Out: every face's
// loop points (Face::points), in loop order, each with its model node: faces that share a B-rep edge
// (TrimEdgeRef, in the same placement) or a vertex put bit-identical 3D points there.
//
// The order of use (the driver, tessellate_to_deviation.cpp):
//   add_face for each face           which segments are which model curve (seams of untrimmed faces too)
//   find_degenerate_curves           curves collapsed to a point (poles, tiny gap closures): one node
//   join_vertices                    curve ends that meet are one node, placed by the first face there
//   sample_curve for each curve      samples by the deviation of the 3D image, on the curve's first face
//   collect_loop_points, split_span  the loop points of each face (shared samples located on the other
//                                    faces); chords too coarse on some face are split, and the faces
//                                    that use them collected again
// A use whose face disagrees with the shared samples by more than D is sampled on its own and counted in
// TessellationReport::unshared_edge_uses (the mesh may have a crack there).
#include <map>
#include <tuple>
#include <vector>

#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "analysis/tessellation/model_curves.hpp"
#include "analysis/tessellation/model_nodes.hpp"
#include "analysis/tessellation/tessellation_face.hpp"
#include "analysis/tessellation/vertex_classes.hpp"

namespace cadnurbs::tessellation {

class SharedEdges {
 public:
  SharedEdges(std::vector<Face>& faces, double max_deviation, TessellationReport& report)
      : faces_(faces), d_(max_deviation), report_(report), nodes_(faces) {}

  // Gives face `face`'s segments their model curves (Face::curve, Face::reversed) and records the uses.
  // An untrimmed face (one domain_loop) gets four sides, opposite sides that coincide in 3D as one curve.
  void add_face(int face);

  void find_degenerate_curves();
  void join_vertices();

  // Samples curve c on the face of its first use (nothing for a degenerate curve).
  void sample_curve(CurveId c);

  // (Re)fills Face::points of face `face` from the curves' current samples.
  void collect_loop_points(int face);

  // A new sample in the middle (in the origin segment's parameter) of the span; every face that uses
  // the curve must collect its loop points again.
  void split_span(CurveSpan span);

  const ModelCurves& curves() const { return curves_; }

 private:
  std::vector<Face>& faces_;
  double d_;
  TessellationReport& report_;
  ModelCurves curves_;
  VertexClasses classes_{0};
  ModelNodes nodes_;
  // Shared samples located on another face (invert_shared_samples), per (face, loop, segment): they
  // depend only on the curve's samples, so a face collected again after a split of some other curve
  // takes them as they were. `splits` is the curve's split count when they were located.
  struct Located {
    int splits = -1;
    std::vector<LoopPoint> points;
  };
  std::map<std::tuple<int, int, int>, Located> located_;
  std::vector<int> splits_;  // per curve index: how often split_span has changed its samples

  const TrimSegment& segment(const CurveUse& u) const { return faces_[u.face].loops[u.loop].segments[u.segment]; }
  CurveUse use_of(int face, int loop, int segment) const;
  NodeId node_at(const CurveUse& u, CurveEndSide of_segment);
  void append_use(Face& f, const CurveUse& use, std::vector<LoopPoint>& out);
  void own_samples(Face& f, const TrimSegment& s, std::vector<LoopPoint>& out);
};

}  // namespace cadnurbs::tessellation
