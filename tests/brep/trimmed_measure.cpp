#include "trimmed_measure.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "analysis/mesh/triangulate_polygon.hpp"
#include "core/nurbs_curve.hpp"
#include "core/nurbs_surface.hpp"
#include "core/point_in_loops.hpp"

namespace cadnurbs::test {

namespace {

// One edge of a loop's polygon: a chord of the trimming curve between parameters t0 and t1 (no curve
// for a polyline piece, which is its own chord).
struct Chord {
  const NurbsCurve* curve = nullptr;
  double t0 = 0, t1 = 0;
};

struct LoopPolygon {
  std::vector<Eigen::Vector2d> points;  // closed: the last point is not repeated
  std::vector<Chord> chords;            // chords[i] joins points[i] and points[i + 1]
};

int span_count(const TrimLoop& loop) {
  int spans = 0;
  for (const auto& segment : loop.segments)
    if (const auto* c = std::get_if<NurbsCurve>(&segment))
      for (int i = c->order - 1; i < c->count(); ++i) spans += c->knots[i] < c->knots[i + 1] ? 1 : 0;
  return spans;
}

// Parameters in (0, 1) where the straight piece a -> b crosses one of the surface's inner knot lines.
std::vector<double> knot_line_crossings(const NurbsSurface& s, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  std::vector<double> out;
  auto cross = [&](const std::vector<double>& knots, int order, int count, int axis) {
    for (int i = order; i < count; ++i)
      if (knots[i] > knots[i - 1] && (knots[i] - a[axis]) * (knots[i] - b[axis]) < 0)
        out.push_back((knots[i] - a[axis]) / (b[axis] - a[axis]));
  };
  cross(s.u_knots, s.u_order, s.u_count, 0);
  cross(s.v_knots, s.v_order, s.v_count, 1);
  std::sort(out.begin(), out.end());
  return out;
}

// Each NURBS span sampled `per_span` times, polylines as they are. Straight pieces (polylines, polynomial
// order-2 curves) are also split where they cross a knot line of the surface: a boundary triangle that
// straddled one would integrate across the kink of |Su x Sv| there.
LoopPolygon loop_chords(const TrimLoop& loop, int per_span, const NurbsSurface& surface) {
  LoopPolygon out;
  auto add_straight = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const NurbsCurve* curve, double t0, double t1) {
    double from = 0;
    for (double s : knot_line_crossings(surface, a, b)) {
      out.points.push_back(a + from * (b - a));
      out.chords.push_back({curve, t0 + from * (t1 - t0), t0 + s * (t1 - t0)});
      from = s;
    }
    out.points.push_back(a + from * (b - a));
    out.chords.push_back({curve, t0 + from * (t1 - t0), t1});
  };
  for (const auto& segment : loop.segments) {
    if (const auto* c = std::get_if<NurbsCurve>(&segment)) {
      const bool straight = c->order == 2 && !c->is_rational();
      for (int i = c->order - 1; i < c->count(); ++i) {
        const double a = c->knots[i], b = c->knots[i + 1];
        if (!(a < b)) continue;
        for (int s = 0; s < per_span; ++s) {
          const double t0 = a + (b - a) * s / per_span, t1 = a + (b - a) * (s + 1) / per_span;
          const Eigen::Vector2d p0 = curve_point(*c, t0).head<2>();
          if (straight) {
            add_straight(p0, curve_point(*c, t1).head<2>(), c, t0, t1);
          } else {
            out.points.push_back(p0);
            out.chords.push_back({c, t0, t1});
          }
        }
      }
    } else {
      const auto& pts = std::get<Polyline2D>(segment).points;
      for (size_t i = 0; i + 1 < pts.size(); ++i) add_straight(pts[i], pts[i + 1], nullptr, 0, 0);
    }
  }
  return out;
}

// The knots strictly inside (lo, hi).
std::vector<double> inner_knots(const std::vector<double>& knots, int order, int count, double lo, double hi) {
  std::vector<double> out;
  const double margin = 1e-9 * (hi - lo);
  for (int i = order - 1; i <= count; ++i)
    if (knots[i] > lo + margin && knots[i] < hi - margin && (out.empty() || knots[i] > out.back())) out.push_back(knots[i]);
  return out;
}

// `count` - 1 values dividing (lo, hi) evenly.
std::vector<double> even_steps(double lo, double hi, int count) {
  std::vector<double> out;
  for (int i = 1; i < count; ++i) out.push_back(lo + (hi - lo) * i / count);
  return out;
}

std::vector<LoopPolygon> domain_polygons(const TrimmedSurface& t) {
  std::vector<LoopPolygon> out;
  if (t.loops.empty()) {
    // The whole domain, its sides divided at the knots and evenly, like the interior grid.
    const auto& s = t.surface;
    auto side = [](const std::vector<double>& knots, int order, int count) {
      std::vector<double> values = even_steps(knots[order - 1], knots[count], 32);
      for (int i = order - 1; i <= count; ++i) values.push_back(knots[i]);
      std::sort(values.begin(), values.end());
      values.erase(std::unique(values.begin(), values.end()), values.end());
      return values;  // from the domain's start to its end
    };
    const auto us = side(s.u_knots, s.u_order, s.u_count), vs = side(s.v_knots, s.v_order, s.v_count);
    LoopPolygon rectangle;
    for (size_t i = 0; i + 1 < us.size(); ++i) rectangle.points.emplace_back(us[i], vs.front());
    for (size_t i = 0; i + 1 < vs.size(); ++i) rectangle.points.emplace_back(us.back(), vs[i]);
    for (size_t i = us.size() - 1; i > 0; --i) rectangle.points.emplace_back(us[i], vs.back());
    for (size_t i = vs.size() - 1; i > 0; --i) rectangle.points.emplace_back(us.front(), vs[i]);
    rectangle.chords.resize(rectangle.points.size());
    out.push_back(rectangle);
    return out;
  }
  // About 1000 points on all loops together, 4 to 32 per span: the slivers make up for few, and many keep
  // the triangles along the boundary from straddling knot lines.
  int spans = 0;
  for (const auto& loop : t.loops) spans += span_count(loop);
  const int per_span = std::clamp(1000 / std::max(spans, 1), 4, 32);
  for (const auto& loop : t.loops) out.push_back(loop_chords(loop, per_span, t.surface));
  return out;
}

// +1 when the kept region lies left of the loop's polygon, -1 when right, 0 when undecided; probed just
// off several of its edges.
int region_side(const std::vector<LoopPolygon>& polygons, size_t loop, double step) {
  std::vector<std::vector<Eigen::Vector2d>> points;
  for (const auto& polygon : polygons) points.push_back(polygon.points);
  const PointInLoops region(points);
  const auto& pts = polygons[loop].points;
  int left = 0, right = 0;
  const size_t n = pts.size();
  for (size_t k = 0; k < 16; ++k) {
    const size_t i = k * n / 16;
    const Eigen::Vector2d a = pts[i], b = pts[(i + 1) % n];
    const Eigen::Vector2d d = b - a;
    if (d.norm() < 10 * step) continue;
    const Eigen::Vector2d mid = 0.5 * (a + b), normal = Eigen::Vector2d(-d.y(), d.x()).normalized();
    const bool l = region.inside(mid + step * normal), r = region.inside(mid - step * normal);
    if (l && !r) ++left;
    if (r && !l) ++right;
  }
  return left > right ? 1 : (right > left ? -1 : 0);
}

double domain_step(const NurbsSurface& s) { return 1e-6 * std::max(s.u_end() - s.u_start(), s.v_end() - s.v_start()); }

// Interior points for the triangulation: an even 16 x 16 grid keeps triangles small, and points along each
// knot line inside (about 1000 on all lines together, 8 to 32 per line) keep them from straddling the
// lines, where |Su x Sv| has kinks.
std::vector<Eigen::Vector2d> interior_points(const NurbsSurface& s, const Eigen::AlignedBox2d& box) {
  const double u0 = box.min().x(), u1 = box.max().x(), v0 = box.min().y(), v1 = box.max().y();
  std::vector<Eigen::Vector2d> out;
  const auto us = even_steps(u0, u1, 16), vs = even_steps(v0, v1, 16);
  for (double u : us)
    for (double v : vs) out.emplace_back(u, v);
  auto u_knots = inner_knots(s.u_knots, s.u_order, s.u_count, u0, u1);
  auto v_knots = inner_knots(s.v_knots, s.v_order, s.v_count, v0, v1);
  // Surfaces with very many knots: every knot line would cost too much; a subset still helps.
  auto thin = [](std::vector<double>& k) {
    constexpr size_t most = 64;
    if (k.size() <= most) return;
    std::vector<double> fewer;
    for (size_t i = 0; i < most; ++i) fewer.push_back(k[i * k.size() / most]);
    k = fewer;
  };
  thin(u_knots);
  thin(v_knots);
  const int per_line = std::clamp(1000 / static_cast<int>(std::max<size_t>(1, u_knots.size() + v_knots.size())), 8, 32);
  for (double u : u_knots)
    for (double v : even_steps(v0, v1, per_line)) out.emplace_back(u, v);
  for (double v : v_knots)
    for (double u : even_steps(u0, u1, per_line)) out.emplace_back(u, v);
  return out;
}

// |Su x Sv| and P . (Su x Sv) / 3 at (u, v), in world coordinates.
struct Integrand {
  const NurbsSurface& surface;
  const Eigen::Affine3d& world;
  std::array<double, 2> operator()(const Eigen::Vector2d& uv) const {
    const auto d = surface_derivatives(surface, uv.x(), uv.y(), 1);
    const Eigen::Vector3d su = world.linear() * d[1][0], sv = world.linear() * d[0][1];
    const Eigen::Vector3d n = su.cross(sv);
    return {n.norm(), (world * d[0][0]).dot(n) / 3.0};
  }
};

// Dunavant's degree-5 rule with 7 points over the triangle abc.
std::array<double, 2> gauss7(const Integrand& f, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                             const Eigen::Vector2d& c) {
  static const double r15 = std::sqrt(15.0);
  static const double a1 = (6 - r15) / 21, b1 = 1 - 2 * a1, w1 = (155 - r15) / 1200;
  static const double a2 = (6 + r15) / 21, b2 = 1 - 2 * a2, w2 = (155 + r15) / 1200;
  static const std::array<std::array<double, 4>, 7> rule = {{{1.0 / 3, 1.0 / 3, 1.0 / 3, 9.0 / 40},
                                                             {b1, a1, a1, w1},
                                                             {a1, b1, a1, w1},
                                                             {a1, a1, b1, w1},
                                                             {b2, a2, a2, w2},
                                                             {a2, b2, a2, w2},
                                                             {a2, a2, b2, w2}}};
  std::array<double, 2> sum{};
  for (const auto& r : rule) {
    const auto v = f(r[0] * a + r[1] * b + r[2] * c);
    sum[0] += r[3] * v[0];
    sum[1] += r[3] * v[1];
  }
  const double area = 0.5 * std::abs((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
  return {sum[0] * area, sum[1] * area};
}

// Signed (u, v) area between a piece of trimming curve and its chord, positive when the curve bulges to
// the left of the chord's direction: Green's theorem along the piece (4-point Gauss-Legendre), closed by
// the chord.
double sliver_area(const Chord& chord) {
  static const std::array<double, 4> x = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                                          0.8611363115940526};
  static const std::array<double, 4> w = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                                          0.3478548451374538};
  const Eigen::Vector2d p0 = curve_point(*chord.curve, chord.t0).head<2>();
  const Eigen::Vector2d p1 = curve_point(*chord.curve, chord.t1).head<2>();
  const Eigen::Vector2d m = 0.5 * (p0 + p1);  // origin near the piece: less cancellation
  const double half = 0.5 * (chord.t1 - chord.t0), centre = 0.5 * (chord.t0 + chord.t1);
  double integral = 0;
  for (int i = 0; i < 4; ++i) {
    const auto d = curve_derivatives(*chord.curve, centre + half * x[i], 1);
    const Eigen::Vector2d p = d[0].head<2>() - m, q = d[1].head<2>();
    integral += w[i] * half * (p.x() * q.y() - p.y() * q.x());
  }
  // The piece from p0 to p1, then the chord back: the chord's own term vanishes about m.
  return -0.5 * integral;
}

}  // namespace

SurfaceMeasure measure_trimmed_surface(const TrimmedSurface& surface, const Eigen::Affine3d& world) {
  const auto polygons = domain_polygons(surface);
  std::vector<std::vector<Eigen::Vector2d>> loops;
  Eigen::AlignedBox2d box;
  for (const auto& p : polygons) {
    loops.push_back(p.points);
    for (const auto& q : p.points) box.extend(q);
  }
  const auto interior = interior_points(surface.surface, box);
  const auto triangulation = triangulate_polygon(loops, interior);
  const Integrand f{surface.surface, world};
  SurfaceMeasure out;
  for (const auto& t : triangulation.triangles) {
    const auto v = gauss7(f, triangulation.points[t[0]], triangulation.points[t[1]], triangulation.points[t[2]]);
    out.area += v[0];
    out.volume += v[1];
  }
  // The polygon's chords cut across the curved trims: where a curve bulges into the kept region, the
  // sliver between chord and curve was counted but lies outside; where it bulges out, the sliver is
  // missing. Each is weighted by the integrand at the middle of its piece of curve.
  const double step = domain_step(surface.surface);
  for (size_t l = 0; l < polygons.size(); ++l) {
    const int side = region_side(polygons, l, step);
    for (const auto& chord : polygons[l].chords) {
      if (!chord.curve) continue;
      const double sliver = sliver_area(chord);
      const auto v = f(curve_point(*chord.curve, 0.5 * (chord.t0 + chord.t1)).head<2>());
      out.area -= side * sliver * v[0];
      out.volume -= side * sliver * v[1];
    }
  }
  return out;
}

SurfaceMeasure measure_mesh(const TriangleMesh& mesh, const Eigen::Affine3d& world) {
  SurfaceMeasure out;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d a = world * mesh.positions[t[0]], b = world * mesh.positions[t[1]], c = world * mesh.positions[t[2]];
    const Eigen::Vector3d n = (b - a).cross(c - a);
    out.area += 0.5 * n.norm();
    out.volume += a.dot(n) / 6.0;  // signed tetrahedron with the origin
  }
  return out;
}

bool region_left_of_loop(const TrimmedSurface& surface, size_t loop) {
  return region_side(domain_polygons(surface), loop, domain_step(surface.surface)) > 0;
}

}  // namespace cadnurbs::test
