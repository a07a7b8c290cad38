#include "analysis/tessellation/shared_sample_inversion.hpp"

#include <algorithm>

#include "analysis/eval/point_inversion.hpp"
#include "core/trim_segment_parameters.hpp"

namespace cadnurbs::tessellation {

namespace {

// Arc length along the 3D image of a segment: the parameter at a given fraction of the length, a start
// for the inversion. Sampled about four times as densely as the shared samples it serves (at least
// twice, at most 16 times per break interval): a start within a fraction of their spacing is all
// Newton needs, and a table of 16 per interval cost 30 evaluations per shared sample on curves of many spans.
class ArcLengthTable {
 public:
  ArcLengthTable(const SurfaceEvaluator& e, const TrimSegment& s, size_t samples) {
    const auto breaks = segment_breaks(s);
    const size_t intervals = breaks.size() - 1;
    const int per = static_cast<int>(std::clamp<size_t>((4 * samples + intervals - 1) / intervals, 2, 16));
    for (size_t i = 0; i + 1 < breaks.size(); ++i)
      for (int k = (i == 0 ? 0 : 1); k <= per; ++k) ts_.push_back(breaks[i] + (breaks[i + 1] - breaks[i]) * k / per);
    Eigen::Vector3d prev = e.point(segment_uv(s, ts_[0]).x(), segment_uv(s, ts_[0]).y());
    for (size_t i = 1; i < ts_.size(); ++i) {
      const Eigen::Vector2d uv = segment_uv(s, ts_[i]);
      const Eigen::Vector3d p = e.point(uv.x(), uv.y());
      lengths_.push_back(lengths_.back() + (p - prev).norm());
      prev = p;
    }
  }

  double t_at(double fraction) const {
    const double target = fraction * lengths_.back();
    const size_t i = std::min(ts_.size() - 2, static_cast<size_t>(std::upper_bound(lengths_.begin(), lengths_.end(), target) -
                                                                  lengths_.begin()) - (target > 0 ? 1 : 0));
    const double span = lengths_[i + 1] - lengths_[i];
    const double w = span > 0 ? std::clamp((target - lengths_[i]) / span, 0.0, 1.0) : 0.0;
    return ts_[i] + w * (ts_[i + 1] - ts_[i]);
  }

 private:
  std::vector<double> ts_, lengths_{0.0};
};

}  // namespace

bool invert_shared_samples(const Face& face, const CurveUse& use, const ModelCurve& curve, NodeId start_node,
                           NodeId end_node, const ModelNodes& nodes, double max_deviation, std::vector<LoopPoint>& out) {
  const double d = max_deviation;
  const SurfaceEvaluator& e = *face.eval;
  const TrimSegment& s = face.loops[use.loop].segments[use.segment];
  const double t0 = segment_t0(s), t1 = segment_t1(s);
  const size_t n = curve.points.size();
  const ArcLengthTable arc_length(e, s, n);
  std::vector<LoopPoint> mine;
  const Eigen::Vector2d start_uv = segment_uv(s, t0), end_uv = segment_uv(s, t1);
  const Eigen::Vector3d start_point = nodes.in_frame_of(start_node, use.face), end_point = nodes.in_frame_of(end_node, use.face);
  if ((e.point(start_uv.x(), start_uv.y()) - start_point).norm() > d || (e.point(end_uv.x(), end_uv.y()) - end_point).norm() > d)
    return false;
  mine.push_back({start_uv, start_point, start_node});
  mine.back().chord = CurveSpan{use.curve, static_cast<int>(use.reversed ? n - 2 : 0)};
  double t_prev = t0;
  for (size_t k = 1; k + 1 < n; ++k) {
    const size_t i = use.reversed ? n - 1 - k : k;
    const double fraction = use.reversed ? 1 - curve.arc[i] : curve.arc[i];
    const Eigen::Vector3d p = nodes.in_frame_of(curve.nodes[i], use.face);
    const CurveProjection on_curve = project_to_trim_curve(e, s, p, std::max(t_prev, arc_length.t_at(fraction)), t_prev, t1);
    if (on_curve.distance > d) return false;
    Eigen::Vector2d uv = on_curve.uv;
    // Two faces' pcurves of one edge may disagree (file tolerances): a shared point may then land
    // on this segment's end, or on its previous point. The uv must still advance, or the mesh
    // merges two model points into one vertex and leaves a T-junction beside the other face.
    double t = on_curve.t;
    if (!(t > t_prev) || !(t < t1)) {
      t = t_prev + 0.5 * (t1 - t_prev);
      uv = segment_uv(s, t);
    }
    // Polish on the surface: the vertex then sits where this surface is nearest to the shared point.
    const SurfaceProjection on_surface = project_to_surface(e, p, uv, 8);
    const double step = (uv - mine.back().uv).norm();
    if (t == on_curve.t && on_surface.distance < on_curve.distance && (on_surface.uv - uv).norm() < 0.01 * step)
      uv = on_surface.uv;
    t_prev = t;
    mine.push_back({uv, p, curve.nodes[i]});
    mine.back().chord = CurveSpan{use.curve, static_cast<int>(use.reversed ? i - 1 : i)};
  }
  out.insert(out.end(), mine.begin(), mine.end());
  return true;
}

}  // namespace cadnurbs::tessellation
