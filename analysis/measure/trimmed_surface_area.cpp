#include "analysis/measure/trimmed_surface_area.hpp"

#include <cmath>

#include "analysis/eval/span_quadrature.hpp"
#include "analysis/eval/surface_evaluator.hpp"
#include "analysis/mesh/triangulate_polygon.hpp"
#include "core/geometry_error.hpp"
#include "core/knot_vector.hpp"
#include "core/point_in_loops.hpp"
#include "core/trim_segment_parameters.hpp"

namespace cadnurbs {

namespace {

// The 6-point Gauss-Legendre rule on [0, 1] (exact to degree 11), in both directions of a cell.
const QuadratureRule& gauss() { return gauss_legendre(6); }

double density(const SurfaceEvaluator& e, const Eigen::Vector2d& uv) {
  const SurfaceJet j = e.jet(uv.x(), uv.y(), 1);
  return j.su.cross(j.sv).norm();
}

// Integral over a (u,v) triangle by the Duffy map (s, t) -> a + s (b - a) + s t (c - b).
double triangle_integral(const SurfaceEvaluator& e, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                         const Eigen::Vector2d& c) {
  const double jac = std::abs((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
  const QuadratureRule& g = gauss();
  double sum = 0;
  for (size_t i = 0; i < g.nodes.size(); ++i)
    for (size_t k = 0; k < g.nodes.size(); ++k) {
      const double s = g.nodes[i], t = g.nodes[k];
      sum += g.weights[i] * g.weights[k] * s * density(e, a + s * (b - a) + s * t * (c - b));
    }
  return sum * jac;
}

// Signed integral over the strip between chord c(t0)-c(t1) and the curve c over [t0, t1]:
// x(tau, s) = (1 - s) chord(tau) + s c(t(tau)); positive when the curve lies right of the chord.
double strip_integral(const SurfaceEvaluator& e, const TrimSegment& seg, double t0, double t1) {
  const Eigen::Vector2d a = segment_uv(seg, t0), b = segment_uv(seg, t1);
  const QuadratureRule& g = gauss();
  double sum = 0;
  for (size_t i = 0; i < g.nodes.size(); ++i) {
    const double tau = g.nodes[i], t = t0 + tau * (t1 - t0);
    const Eigen::Vector2d chord = a + tau * (b - a), curve = segment_uv(seg, t);
    const Eigen::Vector2d dcurve = segment_tangent(seg, t) * (t1 - t0);
    for (size_t k = 0; k < g.nodes.size(); ++k) {
      const double s = g.nodes[k];
      const Eigen::Vector2d x = (1 - s) * chord + s * curve;
      const Eigen::Vector2d dtau = (1 - s) * (b - a) + s * dcurve, ds = curve - chord;
      const double jac = dtau.x() * ds.y() - dtau.y() * ds.x();  // < 0 when ds points right
      sum += g.weights[i] * g.weights[k] * density(e, x) * (-jac);
    }
  }
  return sum;
}

std::vector<double> knot_grid(const std::vector<double>& knots, int order, int count, int per_span) {
  const std::vector<double> b = domain_breaks(knots, order, count);
  std::vector<double> out{b.front()};
  for (size_t i = 0; i + 1 < b.size(); ++i)
    for (int m = 1; m <= per_span; ++m) out.push_back(m == per_span ? b[i + 1] : b[i] + (b[i + 1] - b[i]) * m / per_span);
  return out;
}

double estimate(const TrimmedSurface& t, const SurfaceEvaluator& e, int level) {
  const NurbsSurface& s = t.surface;
  const int per_span = 1 << level;
  const auto us = knot_grid(s.u_knots, s.u_order, s.u_count, per_span);
  const auto vs = knot_grid(s.v_knots, s.v_order, s.v_count, per_span);
  if (t.loops.empty()) {
    double sum = 0;
    for (size_t j = 0; j + 1 < vs.size(); ++j)
      for (size_t i = 0; i + 1 < us.size(); ++i) {
        const Eigen::Vector2d a(us[i], vs[j]), b(us[i + 1], vs[j]), c(us[i + 1], vs[j + 1]), d(us[i], vs[j + 1]);
        sum += triangle_integral(e, a, b, c) + triangle_integral(e, a, c, d);
      }
    return sum;
  }
  // Loops: each curve span in 2^level * 4 chords, polylines as they are.
  struct Chord {
    const TrimSegment* seg;
    double t0, t1;
  };
  std::vector<std::vector<Eigen::Vector2d>> polys;
  std::vector<std::vector<Chord>> chords;
  for (const auto& loop : t.loops) {
    std::vector<Eigen::Vector2d> poly;
    std::vector<Chord> ch;
    for (const auto& seg : loop.segments) {
      const auto br = segment_breaks(seg);
      const bool curved = std::holds_alternative<NurbsCurve>(seg);
      const int n = curved ? 4 * per_span : 1;
      for (size_t i = 0; i + 1 < br.size(); ++i)
        for (int m = 0; m < n; ++m) {
          const double t0 = br[i] + (br[i + 1] - br[i]) * m / n, t1 = br[i] + (br[i + 1] - br[i]) * (m + 1) / n;
          poly.push_back(segment_uv(seg, t0));
          if (curved) ch.push_back({&seg, t0, t1});
        }
    }
    polys.push_back(std::move(poly));
    chords.push_back(std::move(ch));
  }
  // Delaunay in coordinates where an average knot span is a unit square: in raw (u,v) a domain like
  // [0, pi] x [0, 5080] gets slivers that run across knot lines, where the density has kinks.
  const Eigen::Vector2d span_scale((us.size() - 1) / (us.back() - us.front()), (vs.size() - 1) / (vs.back() - vs.front()));
  std::vector<std::vector<Eigen::Vector2d>> scaled_polys = polys;
  for (auto& poly : scaled_polys)
    for (auto& p : poly) p = p.cwiseProduct(span_scale);
  std::vector<Eigen::Vector2d> interior;
  for (double v : vs)
    for (double u : us) interior.push_back(Eigen::Vector2d(u, v).cwiseProduct(span_scale));
  PlanarTriangulation cdt = triangulate_polygon(scaled_polys, interior);
  for (auto& p : cdt.points) p = p.cwiseQuotient(span_scale);
  double sum = 0;
  for (const auto& tri : cdt.triangles) sum += triangle_integral(e, cdt.points[tri[0]], cdt.points[tri[1]], cdt.points[tri[2]]);
  // Strips: which side of each loop the region lies on (even-odd), from a point just left of a chord.
  PointInLoops region(polys);
  for (size_t l = 0; l < polys.size(); ++l) {
    const auto& poly = polys[l];
    size_t longest = 0;
    for (size_t k = 0; k < poly.size(); ++k)
      if ((poly[(k + 1) % poly.size()] - poly[k]).norm() > (poly[(longest + 1) % poly.size()] - poly[longest]).norm()) longest = k;
    const Eigen::Vector2d a = poly[longest], b = poly[(longest + 1) % poly.size()];
    const Eigen::Vector2d left = 0.5 * (a + b) + 1e-7 * Eigen::Vector2d(-(b - a).y(), (b - a).x());
    const double side = region.inside(left) ? 1.0 : -1.0;  // +1: region on the left of the loop
    for (const auto& c : chords[l]) sum += side * strip_integral(e, *c.seg, c.t0, c.t1);
  }
  return sum;
}

}  // namespace

double trimmed_surface_area(const TrimmedSurface& surface, double relative_tolerance) {
  if (!(relative_tolerance > 0)) throw GeometryError("trimmed_surface_area", "the tolerance must be positive");
  validate(surface, "surface");
  const SurfaceEvaluator e(surface.surface);
  double previous = estimate(surface, e, 0);
  for (int level = 1; level <= 7; ++level) {
    const double next = estimate(surface, e, level);
    if (std::abs(next - previous) <= relative_tolerance * std::abs(next)) return next;
    previous = next;
  }
  return previous;
}

}  // namespace cadnurbs
