#include "core/trimmed_surface.hpp"

#include "core/polygon_2d.hpp"

#include <algorithm>
#include <cmath>

#include "core/geometry_error.hpp"

namespace cadnurbs {

Eigen::Vector2d segment_start(const TrimSegment& segment) {
  if (const auto* c = std::get_if<NurbsCurve>(&segment)) return curve_point(*c, c->domain_start()).head<2>();
  return std::get<Polyline2D>(segment).points.front();
}

Eigen::Vector2d segment_end(const TrimSegment& segment) {
  if (const auto* c = std::get_if<NurbsCurve>(&segment)) return curve_point(*c, c->domain_end()).head<2>();
  return std::get<Polyline2D>(segment).points.back();
}

double loop_closure_gap(const TrimLoop& loop) {
  double gap = 0.0;
  const size_t n = loop.segments.size();
  for (size_t i = 0; i < n; ++i)
    gap = std::max(gap, (segment_end(loop.segments[i]) - segment_start(loop.segments[(i + 1) % n])).norm());
  return gap;
}

std::vector<Eigen::Vector2d> loop_polygon(const TrimLoop& loop, int samples_per_span) {
  std::vector<Eigen::Vector2d> out;
  for (const auto& segment : loop.segments) {
    if (const auto* c = std::get_if<NurbsCurve>(&segment)) {
      for (int i = c->order - 1; i < c->count(); ++i) {
        const double a = c->knots[i], b = c->knots[i + 1];
        if (!(a < b)) continue;
        for (int s = 0; s < samples_per_span; ++s)
          out.push_back(curve_point(*c, a + (b - a) * s / samples_per_span).head<2>());
      }
    } else {
      const auto& pts = std::get<Polyline2D>(segment).points;
      out.insert(out.end(), pts.begin(), pts.end() - 1);
    }
  }
  return out;
}

double loop_signed_area(const TrimLoop& loop) { return polygon_signed_area(loop_polygon(loop)); }

TrimLoop reversed(const TrimLoop& loop) {
  TrimLoop out;
  for (auto it = loop.segments.rbegin(); it != loop.segments.rend(); ++it) {
    if (const auto* c = std::get_if<NurbsCurve>(&*it)) {
      out.segments.emplace_back(reversed(*c));
    } else {
      Polyline2D p = std::get<Polyline2D>(*it);
      std::reverse(p.points.begin(), p.points.end());
      out.segments.emplace_back(std::move(p));
    }
  }
  for (auto it = loop.edges.rbegin(); it != loop.edges.rend(); ++it) out.edges.push_back({it->edge, !it->reversed});
  return out;
}

void validate(const TrimmedSurface& trimmed, const std::string& entity, double closure_tolerance) {
  validate(trimmed.surface, entity);
  for (size_t l = 0; l < trimmed.loops.size(); ++l) {
    const std::string loop_name = entity + " loop " + std::to_string(l);
    const auto& loop = trimmed.loops[l];
    if (loop.segments.empty()) throw GeometryError(loop_name, "has no segments");
    if (!loop.edges.empty() && loop.edges.size() != loop.segments.size())
      throw GeometryError(loop_name, std::to_string(loop.edges.size()) + " edge references for " +
                                         std::to_string(loop.segments.size()) + " segments");
    for (size_t s = 0; s < loop.segments.size(); ++s) {
      const std::string seg_name = loop_name + " segment " + std::to_string(s);
      if (const auto* c = std::get_if<NurbsCurve>(&loop.segments[s])) {
        validate(*c, seg_name);
        if (c->dimension != 2) throw GeometryError(seg_name, "trimming curve is not 2D");
      } else {
        const auto& pts = std::get<Polyline2D>(loop.segments[s]).points;
        if (pts.size() < 2) throw GeometryError(seg_name, "polyline has fewer than 2 points");
        for (const auto& p : pts)
          if (!p.allFinite()) throw GeometryError(seg_name, "polyline point is not finite");
      }
    }
    const double gap = loop_closure_gap(loop);
    if (gap > closure_tolerance)
      throw GeometryError(loop_name, "does not close: gap " + std::to_string(gap) + " between segments");
  }
}

TrimLoop domain_loop(const NurbsSurface& s) {
  const Eigen::Vector2d a(s.u_start(), s.v_start()), b(s.u_end(), s.v_start()), c(s.u_end(), s.v_end()),
      d(s.u_start(), s.v_end());
  TrimLoop loop;
  for (const auto& [p, q] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, d}, std::pair{d, a}})
    loop.segments.emplace_back(Polyline2D{{p, q}});
  return loop;
}

}  // namespace cadnurbs
