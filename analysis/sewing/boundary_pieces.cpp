#include "analysis/sewing/boundary_pieces.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <limits>
#include <utility>
#include <variant>

#include "analysis/eval/sample_trim_segment.hpp"
#include "core/knot_vector.hpp"
#include "core/split_curve.hpp"
#include "core/trim_segment_parameters.hpp"

namespace cadnurbs::sewing {

namespace {

constexpr int kSamplesPerSpan = 8;

struct Cut {
  double t;
  VertexId vertex;
};

// The cuts of one piece, by parameter: the vertices other than its ends within `tolerance` of its interior.
// `by_x`: the vertex ids sorted by x, so that only the vertices in the slab of the piece's box are tried.
std::vector<Cut> cuts_of(const Piece& piece, const SurfaceEvaluator& surface,
                         const std::vector<Eigen::Vector3d>& vertices, const std::vector<int>& by_x,
                         double tolerance) {
  Eigen::AlignedBox3d box;
  double spacing = 0;
  for (size_t k = 0; k < piece.points.size(); ++k) {
    box.extend(piece.points[k]);
    if (k > 0) spacing = std::max(spacing, (piece.points[k] - piece.points[k - 1]).norm());
  }
  const double margin = tolerance + 0.5 * spacing;  // the curve may bulge past its samples
  const Eigen::Vector3d lo = box.min().array() - margin, hi = box.max().array() + margin;
  auto first = std::lower_bound(by_x.begin(), by_x.end(), lo.x(), [&](int v, double x) { return vertices[v].x() < x; });
  std::vector<Cut> cuts;
  const double t0 = piece.ts.front(), t1 = piece.ts.back();
  for (auto it = first; it != by_x.end() && vertices[*it].x() <= hi.x(); ++it) {
    const VertexId v{*it};
    const Eigen::Vector3d& p = vertices[v.value];
    if (v == piece.start || v == piece.end || (p.array() < lo.array()).any() || (p.array() > hi.array()).any())
      continue;
    const CurveProjection foot = project_to_piece(piece, surface, p);
    if (foot.distance <= tolerance && foot.t > t0 && foot.t < t1) cuts.push_back({foot.t, v});
  }
  // Ties broken by vertex, so that every standard library gives one order (the browser module's too).
  std::sort(cuts.begin(), cuts.end(),
            [](const Cut& a, const Cut& b) { return a.t < b.t || (a.t == b.t && a.vertex.value < b.vertex.value); });
  return cuts;
}

// The piece as consecutive pieces between its cuts (not sampled).
std::vector<Piece> cut_piece(const Piece& piece, const std::vector<Cut>& cuts) {
  std::vector<Piece> out;
  Piece rest = piece;
  for (const Cut& cut : cuts) {
    Piece before = rest;
    if (const auto* curve = std::get_if<NurbsCurve>(&rest.segment)) {
      if (!(cut.t > curve->domain_start() && cut.t < curve->domain_end())) continue;  // two cuts at one t
      auto [a, b] = split_curve(*curve, cut.t);
      before.segment = std::move(a);
      rest.segment = std::move(b);
    } else {
      const auto& ends = std::get<Polyline2D>(rest.segment).points;
      const Eigen::Vector2d at = segment_uv(piece.segment, cut.t);  // cut.t is on the uncut 2-point piece
      if (at == ends.front() || at == ends.back()) continue;
      before.segment = Polyline2D{{ends.front(), at}};
      rest.segment = Polyline2D{{at, ends.back()}};
    }
    before.end = cut.vertex;
    rest.start = cut.vertex;
    out.push_back(std::move(before));
  }
  out.push_back(std::move(rest));
  return out;
}

}  // namespace

std::vector<Piece> cut_into_pieces(const std::vector<SewFace>& faces, const std::vector<int>& members) {
  std::vector<Piece> pieces;
  auto add = [&](int face, size_t loop, TrimSegment segment) {
    Piece piece;
    piece.face = face;
    piece.loop = static_cast<int>(loop);
    piece.segment = std::move(segment);
    pieces.push_back(std::move(piece));
  };
  for (const int f : members)
    for (size_t l = 0; l < faces[f].trimmed->loops.size(); ++l)
      for (const auto& segment : faces[f].trimmed->loops[l].segments) {
        const auto* polyline = std::get_if<Polyline2D>(&segment);
        if (!polyline) {
          add(f, l, segment);
          continue;
        }
        for (size_t i = 0; i + 1 < polyline->points.size(); ++i)
          if (polyline->points[i] != polyline->points[i + 1])
            add(f, l, Polyline2D{{polyline->points[i], polyline->points[i + 1]}});
      }
  return pieces;
}

// kSamplesPerSpan per knot span of the piece, and as many again per knot line of the surface that a
// sample interval crosses (a straight (u,v) side across a many-patch surface is one span long).
void sample_piece(Piece& piece, const SurfaceEvaluator& surface, double tolerance) {
  const std::vector<double> us = distinct_knots(surface.surface().u_knots),
                            vs = distinct_knots(surface.surface().v_knots);
  piece.ts.clear();
  piece.points.clear();
  const auto breaks = segment_breaks(piece.segment);
  std::vector<double> coarse;
  for (size_t i = 0; i + 1 < breaks.size(); ++i)
    for (int k = (i == 0 ? 0 : 1); k <= kSamplesPerSpan; ++k)
      coarse.push_back(breaks[i] + (breaks[i + 1] - breaks[i]) * k / kSamplesPerSpan);
  Eigen::Vector2d previous = segment_uv(piece.segment, coarse.front());
  piece.ts.push_back(coarse.front());
  for (size_t i = 1; i < coarse.size(); ++i) {
    const Eigen::Vector2d uv = segment_uv(piece.segment, coarse[i]);
    // (lines_between counts -1 for a side that runs along a knot line)
    const int crossed =
        std::max(0, lines_between(us, previous.x(), uv.x())) + std::max(0, lines_between(vs, previous.y(), uv.y()));
    const int steps = 1 + kSamplesPerSpan * crossed;
    for (int k = 1; k <= steps; ++k) piece.ts.push_back(coarse[i - 1] + (coarse[i] - coarse[i - 1]) * k / steps);
    previous = uv;
  }
  for (double t : piece.ts) {
    const Eigen::Vector2d uv = segment_uv(piece.segment, t);
    piece.points.push_back(surface.point(uv.x(), uv.y()));
  }
  piece.is_point = std::all_of(piece.points.begin(), piece.points.end(), [&](const Eigen::Vector3d& p) {
    return (p - piece.points.front()).norm() <= tolerance;
  });
}

CurveProjection project_to_piece(const Piece& piece, const SurfaceEvaluator& surface, const Eigen::Vector3d& p) {
  double best = std::numeric_limits<double>::infinity(), t_start = piece.ts.front();
  for (size_t k = 0; k + 1 < piece.points.size(); ++k) {
    const Eigen::Vector3d chord = piece.points[k + 1] - piece.points[k];
    const double length2 = chord.squaredNorm();
    const double f = length2 > 0 ? std::clamp((p - piece.points[k]).dot(chord) / length2, 0.0, 1.0) : 0.0;
    const double d2 = (piece.points[k] + f * chord - p).squaredNorm();
    if (d2 < best) best = d2, t_start = piece.ts[k] + f * (piece.ts[k + 1] - piece.ts[k]);
  }
  return project_to_trim_curve(surface, piece.segment, p, t_start, piece.ts.front(), piece.ts.back());
}

std::vector<Piece> cut_at_vertices(const std::vector<Piece>& pieces, const std::vector<SewFace>& faces,
                                   const std::vector<Eigen::Vector3d>& vertices, double tolerance,
                                   SewingReport& report) {
  std::vector<int> by_x(vertices.size());
  for (size_t v = 0; v < vertices.size(); ++v) by_x[v] = static_cast<int>(v);
  std::sort(by_x.begin(), by_x.end(), [&](int a, int b) {  // ties by index: one order on every library
    return vertices[a].x() < vertices[b].x() || (vertices[a].x() == vertices[b].x() && a < b);
  });
  std::vector<Piece> cut;
  for (const auto& p : pieces) {
    const SurfaceEvaluator& surface = *faces[p.face].surface;
    const std::vector<Cut> cuts = p.is_point ? std::vector<Cut>{} : cuts_of(p, surface, vertices, by_x, tolerance);
    if (cuts.empty()) {
      cut.push_back(p);
      continue;
    }
    report.cuts += static_cast<long>(cuts.size());
    for (auto& q : cut_piece(p, cuts)) {
      sample_piece(q, surface, tolerance);
      cut.push_back(std::move(q));
    }
  }
  return cut;
}

}  // namespace cadnurbs::sewing
