#include "analysis/tessellation/shared_edges.hpp"

#include <algorithm>
#include <map>
#include <vector>

#include "analysis/eval/sample_trim_segment.hpp"
#include "analysis/mesh/point_hash_grid.hpp"
#include "analysis/tessellation/domain_loop.hpp"
#include "analysis/tessellation/shared_sample_inversion.hpp"
#include "core/trim_segment_parameters.hpp"

namespace cadnurbs::tessellation {

void SharedEdges::add_face(int fi) {
  Face& f = faces_[fi];
  if (f.trimmed->loops.empty()) {
    // The domain's sides; a closed direction's two sides are one curve (the seam).
    const NurbsSurface& s = f.trimmed->surface;
    const Eigen::Vector2d a(s.u_start(), s.v_start()), b(s.u_end(), s.v_start()), c(s.u_end(), s.v_end()),
        d(s.u_start(), s.v_end());
    const double tolerance = 1e-3 * d_;
    std::vector<CurveId> ids(4);
    for (int k = 0; k < 4; ++k) ids[k] = curves_.add(false);
    std::vector<bool> rev(4, false);
    if (sides_coincide(*f.eval, b, c, a, d, tolerance)) ids[3] = ids[1], rev[3] = true;  // u sides: seam
    if (sides_coincide(*f.eval, a, b, d, c, tolerance)) ids[2] = ids[0], rev[2] = true;  // v sides
    f.curve.push_back(ids);
    f.reversed.push_back(rev);
  } else {
    for (const auto& loop : f.loops) {
      std::vector<CurveId> ids;
      std::vector<bool> rev;
      for (size_t k = 0; k < loop.segments.size(); ++k) {
        const TrimEdgeRef ref = loop.edges.empty() ? TrimEdgeRef{} : loop.edges[k];
        ids.push_back(ref.edge < 0 ? curves_.add(true) : curves_.of_edge(f.world, ref.edge));
        rev.push_back(ref.edge >= 0 && ref.reversed);
      }
      f.curve.push_back(ids);
      f.reversed.push_back(rev);
    }
  }
  for (size_t l = 0; l < f.loops.size(); ++l)
    for (size_t k = 0; k < f.loops[l].segments.size(); ++k)
      curves_[f.curve[l][k]].uses.push_back(use_of(fi, static_cast<int>(l), static_cast<int>(k)));
}

CurveUse SharedEdges::use_of(int face, int loop, int segment) const {
  const Face& f = faces_[face];
  return {face, loop, segment, f.curve[loop][segment], static_cast<bool>(f.reversed[loop][segment])};
}

namespace {

// Curve ends closer than this share of D are one model vertex (and a curve that short is one vertex).
constexpr double kSameVertex = 1e-3;

}  // namespace

void SharedEdges::find_degenerate_curves() {
  // Whether every segment of a loop lies within D/2 of its start, asked once per (face, loop).
  std::map<std::pair<int, int>, bool> tiny_loops;
  auto loop_is_tiny = [&](int fi, int li) {
    auto [it, fresh] = tiny_loops.emplace(std::pair{fi, li}, false);
    if (fresh) {
      const Face& f = faces_[fi];
      const auto& segments = f.loops[li].segments;
      it->second = std::all_of(segments.begin(), segments.end(),
                               [&](const TrimSegment& s) { return is_degenerate_segment(*f.eval, s, 0.5 * d_); });
    }
    return it->second;
  };
  // Which curves are one vertex only as gap closures (not as curves shorter than kSameVertex of D).
  std::vector<bool> gap_collapsed(static_cast<size_t>(curves_.size()), false);
  for (int i = 0; i < curves_.size(); ++i) {
    ModelCurve& c = curves_[CurveId{i}];
    if (c.uses.empty()) continue;
    const CurveUse& u = c.uses.front();
    // A gap closure shorter than D/2 is one vertex: sampled on its own it would leave a crack
    // beside the neighbouring face (Ventilator.stp). A loop made only of such segments closes no
    // gap: a small hole read back from a file that names no edges (11752.stp) stays a hole.
    const bool gap_closure = c.unnamed && !loop_is_tiny(u.face, u.loop);
    const SurfaceEvaluator& surface = *faces_[u.face].eval;
    const bool tiny = is_degenerate_segment(surface, segment(u), kSameVertex * d_);
    c.degenerate = tiny || (gap_closure && is_degenerate_segment(surface, segment(u), 0.5 * d_));
    gap_collapsed[static_cast<size_t>(i)] = c.degenerate && !tiny;
  }
  // Consecutive gap closures collapse together: a run of them is one vertex only while its end stays
  // within D/2 of its start. Otherwise a run of short open edges (a sewn file's open rim: the impeller's
  // blades, 61 pieces with several below D/2 in a row) would pull the face's boundary more than D off
  // and leave its triangles uncertified. (Unnamed curves have one use each: a loop's own.)
  for (const Face& f : faces_)
    for (size_t l = 0; l < f.loops.size(); ++l) {
      const auto& ids = f.curve[l];
      const int n = static_cast<int>(ids.size());
      auto collapsed = [&](int k) { return gap_collapsed[static_cast<size_t>(ids[k].index)]; };
      auto corner = [&](int k) {  // the 3D point where segment k starts
        const Eigen::Vector2d uv = segment_start(f.loops[l].segments[k]);
        return f.eval->point(uv.x(), uv.y());
      };
      int first = 0;
      while (first < n && collapsed(first)) ++first;
      if (first == n) continue;  // a tiny loop's segments are never gap closures
      Eigen::Vector3d run_start = corner((first + 1) % n);
      for (int i = 1; i <= n; ++i) {
        const int k = (first + i) % n;
        const Eigen::Vector3d end = corner((k + 1) % n);
        if (!collapsed(k)) {
          run_start = end;
        } else if ((end - run_start).norm() > 0.5 * d_) {
          curves_[ids[k]].degenerate = false;
          run_start = end;
        }
      }
    }
}

void SharedEdges::join_vertices() {
  classes_ = VertexClasses(curves_.size());
  for (int i = 0; i < curves_.size(); ++i)
    if (curves_[CurveId{i}].degenerate)
      classes_.join({CurveId{i}, CurveEndSide::start}, {CurveId{i}, CurveEndSide::end});
  for (size_t fi = 0; fi < faces_.size(); ++fi) {
    const Face& f = faces_[fi];
    for (size_t l = 0; l < f.loops.size(); ++l) {
      const int n = static_cast<int>(f.loops[l].segments.size());
      for (int k = 0; k < n; ++k) {
        const CurveUse a = use_of(static_cast<int>(fi), static_cast<int>(l), k);
        const CurveUse b = use_of(static_cast<int>(fi), static_cast<int>(l), (k + 1) % n);
        classes_.join(a.end(CurveEndSide::end), b.end(CurveEndSide::start));
      }
    }
  }
  // A face's loops may reach one point from two classes: where an inner loop touches the outer loop at
  // a vertex, two nodes a few bits apart would leave the mesh open there (LED_D3.0mm_Horizontal: the lens
  // cylinder tangent to the cut plane). Corners of one face within kSameVertex of D, as curves that short
  // are, are one vertex. Faces that only touch are not joined: their edges say whether they meet.
  for (size_t fi = 0; fi < faces_.size(); ++fi) {
    const Face& f = faces_[fi];
    std::vector<std::pair<CurveEnd, Eigen::Vector3d>> corners;
    for (size_t l = 0; l < f.loops.size(); ++l)
      for (size_t k = 0; k < f.loops[l].segments.size(); ++k) {
        const CurveUse u = use_of(static_cast<int>(fi), static_cast<int>(l), static_cast<int>(k));
        const Eigen::Vector2d uv = segment_start(segment(u));
        corners.emplace_back(u.end(CurveEndSide::start), f.eval->point(uv.x(), uv.y()));
      }
    const double same = kSameVertex * d_;
    PointHashGrid grid(same);
    for (size_t k = 0; k < corners.size(); ++k) {
      grid.find_near(corners[k].second, [&](int j) {
        if ((corners[j].second - corners[k].second).norm() <= same) classes_.join(corners[j].first, corners[k].first);
        return false;
      });
      grid.insert(corners[k].second, static_cast<int>(k));
    }
  }
  // Node ids and positions of the vertex classes, from the first face that reaches them.
  for (int i = 0; i < curves_.size(); ++i)
    for (const CurveUse& u : curves_[CurveId{i}].uses)
      for (const CurveEndSide side : {CurveEndSide::start, CurveEndSide::end}) {
        if (classes_.node(u.end(side))) continue;
        const TrimSegment& s = segment(u);
        const Eigen::Vector2d uv = segment_uv(s, side == CurveEndSide::start ? segment_t0(s) : segment_t1(s));
        classes_.set_node(u.end(side), nodes_.add(faces_[u.face].eval->point(uv.x(), uv.y()), u.face));
      }
}

NodeId SharedEdges::node_at(const CurveUse& u, CurveEndSide of_segment) { return *classes_.node(u.end(of_segment)); }

namespace {

// Interior samples closer than this share of D to a kept neighbour are dropped: another face may
// invert two such samples to one (u,v) and merge them into one vertex where this face keeps two, which
// leaves a sliver hole between the faces (11752.stp read back, a knot line 1.6e-5 mm before an edge's
// end). The chord moves by less than the distance dropped.
constexpr double kCrowdedSample = 1e-3;

void drop_crowded_samples(std::vector<TrimSample>& samples, double distance) {
  if (samples.size() < 3) return;
  const Eigen::Vector3d last = samples.back().point;
  std::vector<TrimSample> kept{samples.front()};
  for (size_t k = 1; k + 1 < samples.size(); ++k)
    if ((samples[k].point - kept.back().point).norm() >= distance && (samples[k].point - last).norm() >= distance)
      kept.push_back(samples[k]);
  kept.push_back(samples.back());
  samples = std::move(kept);
}

}  // namespace

void SharedEdges::sample_curve(CurveId c) {
  ModelCurve& curve = curves_[c];
  if (curve.degenerate) return;
  const CurveUse& u = curve.uses.front();
  const Face& f = faces_[u.face];
  const NodeId n0 = node_at(u, CurveEndSide::start), n1 = node_at(u, CurveEndSide::end);
  auto samples = sample_trim_segment(*f.eval, f.bound, segment(u), d_, nodes_.in_frame_of(n0, u.face),
                                     nodes_.in_frame_of(n1, u.face), &f.us, &f.vs);
  drop_crowded_samples(samples, kCrowdedSample * d_);
  if (u.reversed) std::reverse(samples.begin(), samples.end());
  const NodeId first_node = u.reversed ? n1 : n0, last_node = u.reversed ? n0 : n1;
  double length = 0;
  for (size_t k = 0; k < samples.size(); ++k) {
    if (k > 0) length += (samples[k].point - samples[k - 1].point).norm();
    curve.points.push_back(samples[k].point);
    curve.uvs.push_back(samples[k].uv);
    curve.ts.push_back(samples[k].t);
    curve.arc.push_back(length);
    curve.nodes.push_back(k == 0 ? first_node : k + 1 == samples.size() ? last_node : nodes_.add(samples[k].point, u.face));
  }
  for (auto& a : curve.arc) a = length > 0 ? a / length : 0;
}

void SharedEdges::collect_loop_points(int fi) {
  Face& f = faces_[fi];
  f.points.assign(f.loops.size(), {});
  for (size_t l = 0; l < f.loops.size(); ++l)
    for (size_t k = 0; k < f.loops[l].segments.size(); ++k)
      append_use(f, use_of(fi, static_cast<int>(l), static_cast<int>(k)), f.points[l]);
}

// Points of one segment use, start included, end excluded (it starts the next segment).
void SharedEdges::append_use(Face& f, const CurveUse& use, std::vector<LoopPoint>& out) {
  const TrimSegment& s = segment(use);
  const ModelCurve& curve = curves_[use.curve];
  const double t0 = segment_t0(s), t1 = segment_t1(s);
  const NodeId start_node = node_at(use, CurveEndSide::start);
  if (curve.degenerate) {
    out.push_back({segment_uv(s, t0), nodes_.in_frame_of(start_node, use.face), start_node, &s, t0, t1});
    return;
  }
  const CurveUse& origin = curve.uses.front();
  if (origin.face == use.face && origin.loop == use.loop && origin.segment == use.segment) {
    // Sampled here: the stored samples, in this segment's direction.
    const size_t n = curve.points.size();
    for (size_t k = 0; k + 1 < n; ++k) {
      const size_t i = use.reversed ? n - 1 - k : k;
      out.push_back({curve.uvs[i], curve.points[i], curve.nodes[i]});
      out.back().chord = CurveSpan{use.curve, static_cast<int>(use.reversed ? i - 1 : i)};
    }
    return;
  }
  const int splits = use.curve.index < static_cast<int>(splits_.size()) ? splits_[use.curve.index] : 0;
  Located& located = located_[{use.face, use.loop, use.segment}];
  if (located.splits != splits) {
    located.points.clear();
    if (!invert_shared_samples(f, use, curve, start_node, node_at(use, CurveEndSide::end), nodes_, d_, located.points)) {
      located.splits = -1;  // not kept: sampled on its own, with nodes of its own, each time
      ++report_.unshared_edge_uses;
      own_samples(f, s, out);
      return;
    }
    located.splits = splits;
  }
  out.insert(out.end(), located.points.begin(), located.points.end());
}

// The segment sampled on this face alone, with nodes of its own.
void SharedEdges::own_samples(Face& f, const TrimSegment& s, std::vector<LoopPoint>& out) {
  const Eigen::Vector2d a = segment_uv(s, segment_t0(s)), b = segment_uv(s, segment_t1(s));
  const Eigen::Vector3d pa = f.eval->point(a.x(), a.y()), pb = f.eval->point(b.x(), b.y());
  const auto samples = sample_trim_segment(*f.eval, f.bound, s, d_, pa, pb, &f.us, &f.vs);
  for (size_t k = 0; k + 1 < samples.size(); ++k)
    out.push_back({samples[k].uv, samples[k].point, nodes_.add(samples[k].point, static_cast<int>(&f - faces_.data()))});
}

void SharedEdges::split_span(CurveSpan which) {
  ModelCurve& curve = curves_[which.curve];
  if (which.curve.index >= static_cast<int>(splits_.size())) splits_.resize(which.curve.index + 1, 0);
  ++splits_[which.curve.index];
  const int span = which.span;
  const CurveUse& u = curve.uses.front();
  const TrimSegment& s = segment(u);
  const double t = 0.5 * (curve.ts[span] + curve.ts[span + 1]);
  const Eigen::Vector2d uv = segment_uv(s, t);
  const Eigen::Vector3d p = faces_[u.face].eval->point(uv.x(), uv.y());
  const auto at = static_cast<std::ptrdiff_t>(span + 1);
  curve.points.insert(curve.points.begin() + at, p);
  curve.uvs.insert(curve.uvs.begin() + at, uv);
  curve.ts.insert(curve.ts.begin() + at, t);
  curve.nodes.insert(curve.nodes.begin() + at, nodes_.add(p, u.face));
  curve.arc.assign(1, 0.0);
  for (size_t k = 1; k < curve.points.size(); ++k) curve.arc.push_back(curve.arc.back() + (curve.points[k] - curve.points[k - 1]).norm());
  for (auto& a : curve.arc) a = curve.arc.back() > 0 ? a / curve.arc.back() : 0;
}

}  // namespace cadnurbs::tessellation
