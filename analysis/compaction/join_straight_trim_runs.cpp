#include "analysis/compaction/join_straight_trim_runs.hpp"

#include <algorithm>

namespace cadnurbs {

namespace {

double distance_to_segment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double length2 = ab.squaredNorm();
  if (length2 == 0.0) return (p - a).norm();
  const double t = std::clamp((p - a).dot(ab) / length2, 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

}  // namespace

std::optional<std::vector<Eigen::Vector2d>> straight_segment_points(const TrimSegment& segment, double tolerance) {
  if (const auto* polyline = std::get_if<Polyline2D>(&segment)) return polyline->points;
  const auto& curve = std::get<NurbsCurve>(segment);
  std::vector<Eigen::Vector2d> points;
  for (const auto& p : curve.points) points.push_back(p.head<2>());
  if (curve.order == 2) return points;
  // Clamped ends are the first and last control points; otherwise the curve does not start there.
  const bool clamped = curve.knots.front() == curve.knots[curve.order - 1] &&
                       curve.knots[curve.points.size()] == curve.knots.back();
  if (!clamped || points.size() < 2) return std::nullopt;
  const Eigen::Vector2d a = points.front(), b = points.back();
  const Eigen::Vector2d ab = b - a;
  const double length2 = ab.squaredNorm();
  if (length2 == 0.0) return std::nullopt;
  double previous = 0.0;
  for (const auto& p : points) {
    const double t = (p - a).dot(ab) / length2;
    if (t < previous - 1e-12 || t > 1.0 + 1e-12 || distance_to_segment(p, a, b) > tolerance) return std::nullopt;
    previous = t;
  }
  return std::vector<Eigen::Vector2d>{a, b};
}

std::vector<Eigen::Vector2d> without_collinear_points(const std::vector<Eigen::Vector2d>& points, double tolerance) {
  if (points.size() <= 2) return points;
  std::vector<Eigen::Vector2d> out = {points.front()};
  size_t anchor = 0;
  for (size_t next = 2; next < points.size(); ++next) {
    // Can the line anchor -> next stand for every point between them?
    bool covers = true;
    for (size_t k = anchor + 1; k < next && covers; ++k)
      covers = distance_to_segment(points[k], points[anchor], points[next]) <= tolerance;
    if (!covers) {
      anchor = next - 1;
      out.push_back(points[anchor]);
    }
  }
  out.push_back(points.back());
  return out;
}

TrimLoop join_straight_trim_runs(const TrimLoop& loop, double tolerance, int* runs) {
  const size_t n = loop.segments.size();
  std::vector<std::optional<std::vector<Eigen::Vector2d>>> straight(n);
  for (size_t i = 0; i < n; ++i) straight[i] = straight_segment_points(loop.segments[i], tolerance);
  size_t start = 0;
  while (start < n && straight[start]) ++start;
  if (start == n) start = 0;  // straight all round

  TrimLoop out;
  const bool has_edges = loop.edges.size() == n;
  auto flush = [&](std::vector<Eigen::Vector2d>& run, int pieces, const TrimEdgeRef& edge) {
    if (pieces == 0) return;
    Polyline2D polyline{without_collinear_points(run, tolerance)};
    out.segments.emplace_back(std::move(polyline));
    if (has_edges) out.edges.push_back(pieces == 1 ? edge : TrimEdgeRef{});
    if (pieces > 1 && runs) ++*runs;
    run.clear();
  };
  std::vector<Eigen::Vector2d> run;
  int pieces = 0;
  TrimEdgeRef first_edge;
  for (size_t k = 0; k < n; ++k) {
    const size_t i = (start + k) % n;
    if (!straight[i]) {
      flush(run, pieces, first_edge);
      pieces = 0;
      out.segments.push_back(loop.segments[i]);
      if (has_edges) out.edges.push_back(loop.edges[i]);
      continue;
    }
    const auto& points = *straight[i];
    if (pieces == 0) {
      run = points;
      if (has_edges) first_edge = loop.edges[i];
    } else {
      run.insert(run.end(), points.begin() + 1, points.end());  // the joint is the previous end
    }
    ++pieces;
  }
  flush(run, pieces, first_edge);
  return out;
}

}  // namespace cadnurbs
