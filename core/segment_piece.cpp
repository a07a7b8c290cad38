#include "core/segment_piece.hpp"

#include <cmath>

#include "core/split_curve.hpp"
#include "core/trim_segment_parameters.hpp"

namespace cadnurbs {

TrimSegment segment_piece(const TrimSegment& segment, double t0, double t1) {
  if (const auto* c = std::get_if<NurbsCurve>(&segment)) {
    NurbsCurve piece = *c;
    if (t1 < piece.domain_end()) piece = split_curve(piece, t1).first;
    if (t0 > piece.domain_start()) piece = split_curve(piece, t0).second;
    return piece;
  }
  const auto& points = std::get<Polyline2D>(segment).points;
  Polyline2D piece;
  piece.points.push_back(segment_uv(segment, t0));
  for (size_t i = static_cast<size_t>(std::floor(t0)) + 1; double(i) < t1; ++i) piece.points.push_back(points[i]);
  piece.points.push_back(segment_uv(segment, t1));
  return piece;
}

void set_segment_start(TrimSegment& segment, const Eigen::Vector2d& p) {
  if (auto* c = std::get_if<NurbsCurve>(&segment)) c->points.front().head<2>() = p;
  else std::get<Polyline2D>(segment).points.front() = p;
}

void set_segment_end(TrimSegment& segment, const Eigen::Vector2d& p) {
  if (auto* c = std::get_if<NurbsCurve>(&segment)) c->points.back().head<2>() = p;
  else std::get<Polyline2D>(segment).points.back() = p;
}

}  // namespace cadnurbs
