#include "analysis/tessellate_to_deviation.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <numeric>
#include <optional>
#include <set>
#include <unordered_map>
#include <unordered_set>

#include "analysis/domain_triangulation.hpp"
#include "analysis/point_inversion.hpp"
#include "analysis/point_triangle_distance.hpp"
#include "analysis/sample_trim_segment.hpp"
#include "analysis/surface_deviation_bound.hpp"
#include "analysis/surface_evaluator.hpp"
#include "core/geometry_error.hpp"
#include "core/point_in_loops.hpp"

namespace cadnurbs {

namespace {

// ---------------------------------------------------------------------------------------------
// Shared model geometry: vertices (classes of segment ends) and curves (edges) over all faces.

// One point of a face's loop, in loop order. `degenerate` set: the loop runs from here to the next
// point along that collapsed segment (all its points are this one 3D point).
struct LoopPoint {
  Eigen::Vector2d uv;
  Eigen::Vector3d point;
  int node;  // model node id: points with the same node are one mesh vertex
  const TrimSegment* degenerate = nullptr;
  double t = 0, t_next = 0;
  // The chord from here to the next point is span `span` (samples span, span + 1) of model curve
  // `curve`; -1 when it cannot be split (a collapsed segment, or samples of its own).
  int curve = -1, span = -1;
};

struct Face {
  const TrimmedSurface* trimmed = nullptr;
  std::string name;
  Eigen::Affine3d world = Eigen::Affine3d::Identity();
  std::unique_ptr<SurfaceEvaluator> eval;
  SurfaceDeviationBound bound;
  std::vector<TrimLoop> loops;                 // the face's loops (a rectangle when untrimmed)
  std::vector<std::vector<int>> curve;         // model curve per segment
  std::vector<std::vector<bool>> reversed;     // segment runs against its curve
  std::vector<std::vector<LoopPoint>> points;  // filled by sharing, consumed by meshing
  std::vector<double> us, vs;                  // the tensor grid (plan_grid)
  TriangleMesh mesh;
};

struct CurveUse {
  int face, loop, segment;
  bool reversed;
};

struct ModelCurve {
  std::vector<CurveUse> uses;
  bool degenerate = false;
  bool unnamed = false;  // a trim segment of no B-rep edge (a gap closure formats/brep added)
  std::vector<Eigen::Vector3d> points;  // in curve direction, ends included, origin face frame
  std::vector<Eigen::Vector2d> uvs;     // on the origin face
  std::vector<int> nodes;
  std::vector<double> ts;   // parameters on the origin segment
  std::vector<double> arc;  // cumulative chord length fraction
};

struct UnionFind {
  std::vector<int> parent;
  int add() {
    parent.push_back(static_cast<int>(parent.size()));
    return parent.back();
  }
  int find(int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(int a, int b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

// Su x Sv is a usable normal: not zero, and not the cross product of a round-off Su (or Sv) at a
// pole, which a test relative to |Su| |Sv| would accept.
bool has_normal(const SurfaceJet& j) {
  return j.su.cross(j.sv).norm() > 1e-9 * (j.su.squaredNorm() + j.sv.squaredNorm());
}

Eigen::Vector3d normal_at(const SurfaceEvaluator& e, const Eigen::Vector2d& uv) {
  const double du = e.u_end() - e.u_start(), dv = e.v_end() - e.v_start();
  for (double step : {0.0, 1e-7, 1e-5, 1e-3}) {
    const double u = uv.x() + (uv.x() < e.u_start() + 0.5 * du ? step : -step) * du;
    const double v = uv.y() + (uv.y() < e.v_start() + 0.5 * dv ? step : -step) * dv;
    const SurfaceJet j = e.jet(u, v, 1);
    if (has_normal(j)) return j.su.cross(j.sv).normalized();
  }
  return Eigen::Vector3d::Zero();
}

double control_net_size(const NurbsSurface& s) {
  Eigen::AlignedBox3d box;
  for (const auto& p : s.points) box.extend(p);
  return box.diagonal().norm();
}

// A rectangle loop around the whole domain: (v0 side, u1 side, v1 side, u0 side), counter-clockwise.
TrimLoop domain_loop(const NurbsSurface& s) {
  const Eigen::Vector2d a(s.u_start(), s.v_start()), b(s.u_end(), s.v_start()), c(s.u_end(), s.v_end()),
      d(s.u_start(), s.v_end());
  TrimLoop loop;
  for (const auto& [p, q] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, d}, std::pair{d, a}})
    loop.segments.emplace_back(Polyline2D{{p, q}});
  return loop;
}

// True when the (u,v) lines a0-a1 and b0-b1 map to the same 3D curve, point for point.
bool sides_coincide(const SurfaceEvaluator& e, const Eigen::Vector2d& a0, const Eigen::Vector2d& a1,
                    const Eigen::Vector2d& b0, const Eigen::Vector2d& b1, double tolerance) {
  for (int k = 0; k <= 16; ++k) {
    const double s = k / 16.0;
    const Eigen::Vector2d p = (1 - s) * a0 + s * a1, q = (1 - s) * b0 + s * b1;
    if ((e.point(p.x(), p.y()) - e.point(q.x(), q.y())).norm() > tolerance) return false;
  }
  return true;
}

  // Positive root y of q y^2 + c y + r = 0 (r < 0), as a step fraction in (0, 1].
double positive_root(double q, double c, double r) {
    if (q <= 0) return c > 0 ? std::min(1.0, -r / c) : 1.0;
    const double y = (-c + std::sqrt(c * c - 4 * q * r)) / (2 * q);
    return std::clamp(y, 1e-9, 1.0);
  }

// Grid lines over the knot spans b (span i wants `steps[i]` cells). The wanted density steps[i] /
// length is integrated between hard lines (the ends and the C0 knots in `hard`), and lines go at equal
// shares of it: a run of thin knot spans (linkrods.step: nine within 1e-4 of each other) then shares
// cells with its neighbours instead of adding a row of slivers each.
std::vector<double> graded(const std::vector<double>& b, const std::vector<double>& steps, const std::vector<double>& hard) {
  std::vector<double> stops{b.front()};
  for (double x : hard)
    if (x > b.front() && x < b.back()) stops.push_back(x);
  stops.push_back(b.back());
  std::vector<double> out{b.front()};
  size_t i = 0;  // span holding the walk
  for (size_t h = 0; h + 1 < stops.size(); ++h) {
    const double from = stops[h], to = stops[h + 1];
    // Cumulative wanted cells at each span end within [from, to].
    std::vector<double> xs{from}, cells{0.0};
    for (size_t k = i; k + 1 < b.size() && b[k] < to; ++k) {
      const double lo = std::max(b[k], from), hi = std::min(b[k + 1], to);
      if (hi <= lo) continue;
      xs.push_back(hi);
      cells.push_back(cells.back() + steps[k] * (hi - lo) / (b[k + 1] - b[k]));
    }
    while (i + 1 < b.size() && b[i + 1] <= to) ++i;
    const int n = std::max(1, static_cast<int>(std::ceil(cells.back() - 1e-9)));
    size_t k = 1;
    for (int line = 1; line < n; ++line) {
      const double target = cells.back() * line / n;
      while (cells[k] < target) ++k;
      const double w = (target - cells[k - 1]) / (cells[k] - cells[k - 1]);
      out.push_back(xs[k - 1] + w * (xs[k] - xs[k - 1]));
    }
    out.push_back(to);
  }
  return out;
}

  // Liang-Barsky: does segment ab meet the box?
bool segment_meets_box(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double x0, double x1, double y0,
                                double y1) {
    double t0 = 0, t1 = 1;
    const Eigen::Vector2d d = b - a;
    const double p[4] = {-d.x(), d.x(), -d.y(), d.y()};
    const double q[4] = {a.x() - x0, x1 - a.x(), a.y() - y0, y1 - a.y()};
    for (int k = 0; k < 4; ++k) {
      if (p[k] == 0) {
        if (q[k] < 0) return false;
      } else {
        const double r = q[k] / p[k];
        if (p[k] < 0) t0 = std::max(t0, r);
        else t1 = std::min(t1, r);
        if (t0 > t1) return false;
      }
    }
    return true;
  }


// The tensor grid of a face (see the header, step 1): us and vs, C0 knot values included.
void plan_grid(Face& f, const std::vector<std::vector<Eigen::Vector2d>>& polys, double d) {
    const SurfaceEvaluator& e_ = *f.eval;
    const auto& ub = f.bound.u_breaks;
    const auto& vb = f.bound.v_breaks;
    const int nu = static_cast<int>(ub.size()) - 1, nv = static_cast<int>(vb.size()) - 1;
    std::vector<char> used(static_cast<size_t>(nu) * nv, 0);
    PointInLoops region(polys);
    auto cell_of = [](const std::vector<double>& b, double x) {
      const int n = static_cast<int>(b.size()) - 1;
      return std::clamp(static_cast<int>(std::upper_bound(b.begin(), b.end(), x) - b.begin()) - 1, 0, n - 1);
    };
    for (const auto& poly : polys)
      for (size_t k = 0; k < poly.size(); ++k) {
        const Eigen::Vector2d& a = poly[k];
        const Eigen::Vector2d& b = poly[(k + 1) % poly.size()];
        const int i0 = cell_of(ub, std::min(a.x(), b.x())), i1 = cell_of(ub, std::max(a.x(), b.x()));
        const int j0 = cell_of(vb, std::min(a.y(), b.y())), j1 = cell_of(vb, std::max(a.y(), b.y()));
        for (int j = j0; j <= j1; ++j)
          for (int i = i0; i <= i1; ++i)
            if (segment_meets_box(a, b, ub[i], ub[i + 1], vb[j], vb[j + 1])) used[i + j * nu] = 1;
      }
    for (int j = 0; j < nv; ++j)
      for (int i = 0; i < nu; ++i)
        if (region.inside({0.5 * (ub[i] + ub[i + 1]), 0.5 * (vb[j] + vb[j + 1])})) used[i + j * nu] = 1;

    const double target = 0.85 * d;
    std::vector<double> steps_u(nu, 0.0), steps_v(nv, 0.0);  // wanted cells per span (fractional)
    for (int j = 0; j < nv; ++j)
      for (int i = 0; i < nu; ++i) {
        if (!used[i + j * nu]) continue;
        const double hu = ub[i + 1] - ub[i], hv = vb[j + 1] - vb[j];
        // Second derivatives sampled on a 4 x 4 lattice of the patch: an estimate, the certificate
        // decides.
        double muu = 0, muv = 0, mvv = 0, fuu = 0, fuv = 0, fvv = 0;
        bool any_normal = false;
        for (int b = 0; b <= 3; ++b)
          for (int a = 0; a <= 3; ++a) {
            const SurfaceJet jet = e_.jet(ub[i] + hu * a / 3, vb[j] + hv * b / 3, 2);
            fuu = std::max(fuu, jet.suu.norm()), fuv = std::max(fuv, jet.suv.norm()), fvv = std::max(fvv, jet.svv.norm());
            // Normal components (the second fundamental form): tangential acceleration moves points
            // within the surface and costs no deviation. Points without a normal (poles) are skipped.
            const Eigen::Vector3d n = jet.su.cross(jet.sv);
            if (!has_normal(jet)) continue;
            const Eigen::Vector3d un = n.normalized();
            muu = std::max(muu, std::abs(un.dot(jet.suu))), muv = std::max(muv, std::abs(un.dot(jet.suv)));
            mvv = std::max(mvv, std::abs(un.dot(jet.svv)));
            any_normal = true;
          }
        if (!any_normal) muu = fuu, muv = fuv, mvv = fvv;
        // One-step errors of the cell in each direction, and the mixed term.
        const double a = muu * hu * hu / 8, b = mvv * hv * hv / 8, c = 2 * muv * hu * hv / 8;
        // Step fractions 1 / n. A patch already within the target may share a cell with its
        // neighbours: x = y > 1 then, and a flat patch wants no cell of its own at all.
        const double whole = a + b + c;
        double x = whole > 0 ? std::sqrt(target / whole) : 1e9, y = x;
        if (whole > target) {
          x = y = 1;
          if (a <= 0 || b <= 0) {
            // One direction is straight: all of the budget to the other.
            if (a > 0) x = positive_root(a, c, b - target);
            if (b > 0) y = positive_root(b, c, a - target);
            if (a <= 0 && c <= 0) x = 1e9;  // straight and untwisted: no need to step at all
            if (b <= 0 && c <= 0) y = 1e9;
            if (a <= 0 && b <= 0) x = y = std::sqrt(target / c);
          } else {
            const double t2 = target / (2 + c / std::sqrt(a * b));
            x = std::sqrt(t2 / a), y = std::sqrt(t2 / b);
            if (x > 1) x = 1, y = positive_root(b, c, a - target);
            else if (y > 1) y = 1, x = positive_root(a, c, b - target);
          }
        }
        steps_u[i] = std::max(steps_u[i], std::min(4096.0, 1 / std::max(x, 1e-9)));
        steps_v[j] = std::max(steps_v[j], std::min(4096.0, 1 / std::max(y, 1e-9)));
      }
    f.us = graded(ub, steps_u, f.bound.c0_u);
    f.vs = graded(vb, steps_v, f.bound.c0_v);
  }


// ---------------------------------------------------------------------------------------------
// Meshing one face from its loop points.

class FaceMesher {
 public:
  FaceMesher(Face& face, double d, TessellationReport& report) : f_(face), e_(*face.eval), d_(d), report_(report) {}

  void run() {
    us_ = f_.us;
    vs_ = f_.vs;
    build_triangulation();
    refine();
    emit();
  }

 private:
  struct Vertex {
    Eigen::Vector2d uv;
    Eigen::Vector3d point;
    Eigen::Vector3d error;  // S(uv) - point
    int node;               // -1: own vertex
  };
  struct Verdict {
    bool ok = true;
    double bound = 0;     // certified bound (when ok) or largest sampled error
    double sampled = 0;   // largest sampled error
    int edge = -1;        // edge (0: a-b, 1: b-c, 2: c-a) where the sampled error peaks, -1 inside
    Eigen::Vector2d peak;
    bool crosses_c0 = false;
    Eigen::Vector2d c0_point;
  };

  Face& f_;
  const SurfaceEvaluator& e_;
  double d_;
  TessellationReport& report_;
  std::vector<double> us_, vs_;  // grid parameters (knots included)
  std::unique_ptr<DomainTriangulation> dt_;
  std::vector<Vertex> vertices_;
  std::unordered_set<std::uint64_t> certified_;  // hashes of certified triangles
  std::vector<std::array<int, 3>> triangles_;

  std::vector<std::vector<Eigen::Vector2d>> polygons() const {
    std::vector<std::vector<Eigen::Vector2d>> out;
    for (const auto& loop : f_.points) {
      std::vector<Eigen::Vector2d> poly;
      for (const auto& p : loop) poly.push_back(p.uv);
      out.push_back(std::move(poly));
    }
    return out;
  }

  // -- 2. triangulation -------------------------------------------------------------------------
  int add_vertex(const Eigen::Vector2d& uv, const Eigen::Vector3d& point, int node) {
    const int id = dt_->insert(uv);
    sync_vertices();
    if (id == static_cast<int>(vertices_.size()) - 1 && vertices_[id].node == -2) set_vertex(id, uv, point, node);
    return id;
  }

  void set_vertex(int id, const Eigen::Vector2d& uv, const Eigen::Vector3d& point, int node) {
    vertices_[id] = {uv, point, e_.point(uv.x(), uv.y()) - point, node};
  }

  // New triangulation vertices (insertions, constraint crossings) get placeholder records first.
  void sync_vertices() {
    while (static_cast<int>(vertices_.size()) < dt_->vertex_count()) {
      const int id = static_cast<int>(vertices_.size());
      const Eigen::Vector2d uv = dt_->uv(id);
      vertices_.push_back({uv, e_.point(uv.x(), uv.y()), Eigen::Vector3d::Zero(), -2});
    }
  }

  void build_triangulation() {
    const double su = (us_.size() - 1) / (us_.back() - us_.front());
    const double sv = (vs_.size() - 1) / (vs_.back() - vs_.front());
    dt_ = std::make_unique<DomainTriangulation>(su, sv);
    // Loops first, with degenerate runs split to the grid's resolution.
    std::vector<std::vector<Eigen::Vector2d>> polys;
    for (const auto& loop : f_.points) {
      std::vector<int> ids;
      std::vector<Eigen::Vector2d> poly, given;
      for (size_t k = 0; k < loop.size(); ++k) {
        const LoopPoint& p = loop[k];
        given.push_back(p.uv);
        const Eigen::Vector2d uv = inside_domain(p.uv);
        ids.push_back(add_vertex(uv, p.point, p.node));
        poly.push_back(uv);
        if (!p.degenerate) continue;
        const Eigen::Vector2d next = loop[(k + 1) % loop.size()].uv;
        const int n = 1 + lines_between(us_, p.uv.x(), next.x()) + lines_between(vs_, p.uv.y(), next.y());
        for (int s = 1; s < n; ++s) {
          const Eigen::Vector2d along = inside_domain(segment_uv(*p.degenerate, p.t + (p.t_next - p.t) * s / n));
          ids.push_back(add_vertex(along, p.point, p.node));
          poly.push_back(along);
        }
      }
      if (ids.size() < 3) throw GeometryError(f_.name, "a trimming loop has fewer than 3 distinct points");
      check_loop(given, polys.size());
      dt_->insert_loop(ids);
      sync_vertices();
      polys.push_back(std::move(poly));
    }
    for (auto& v : vertices_)
      if (v.node == -2) v.node = -1, v.error = Eigen::Vector3d::Zero();  // constraint crossings
    // Grid points inside the loops, away from them.
    PointInLoops region(polys);
    const int nu = static_cast<int>(us_.size()), nv = static_cast<int>(vs_.size());
    std::vector<char> blocked(static_cast<size_t>(nu) * nv, 0);
    auto half = [](const std::vector<double>& g, int i) {
      const double l = i > 0 ? g[i] - g[i - 1] : g[1] - g[0];
      const double r = i + 1 < static_cast<int>(g.size()) ? g[i + 1] - g[i] : l;
      return 0.35 * std::min(l, r);
    };
    for (const auto& poly : polys)
      for (size_t k = 0; k < poly.size(); ++k) {
        const Eigen::Vector2d& a = poly[k];
        const Eigen::Vector2d& b = poly[(k + 1) % poly.size()];
        const int i0 = index_at_or_below(us_, std::min(a.x(), b.x())), i1 = index_at_or_below(us_, std::max(a.x(), b.x())) + 1;
        const int j0 = index_at_or_below(vs_, std::min(a.y(), b.y())), j1 = index_at_or_below(vs_, std::max(a.y(), b.y())) + 1;
        for (int j = std::max(0, j0); j <= std::min(nv - 1, j1); ++j)
          for (int i = std::max(0, i0); i <= std::min(nu - 1, i1); ++i) {
            const double hu = half(us_, i), hv = half(vs_, j);
            if (segment_meets_box(a, b, us_[i] - hu, us_[i] + hu, vs_[j] - hv, vs_[j] + hv)) blocked[i + j * nu] = 1;
          }
      }
    for (int j = 0; j < nv; ++j) {
      const std::vector<double> cross = region.crossings(vs_[j]);
      for (int i = 0; i < nu; ++i) {
        if (blocked[i + j * nu]) continue;
        const auto below = std::lower_bound(cross.begin(), cross.end(), us_[i]) - cross.begin();
        if (below % 2 == 0) continue;
        const Eigen::Vector2d uv(us_[i], vs_[j]);
        add_vertex(uv, e_.point(uv.x(), uv.y()), -1);
      }
    }
  }

  // Refuses loops that bound nothing or leave the surface's domain by more than 1e-2 of it. Files put
  // pcurves a little outside (11752.stp: 1.5e-3 of a B-spline's domain); their points are moved onto
  // the domain's edge (inside_domain), where the surface is clamped anyway.
  void check_loop(const std::vector<Eigen::Vector2d>& poly, size_t index) const {
    const double du = e_.u_end() - e_.u_start(), dv = e_.v_end() - e_.v_start();
    double area = 0;
    for (size_t k = 0; k < poly.size(); ++k) {
      const Eigen::Vector2d& a = poly[k];
      const Eigen::Vector2d& b = poly[(k + 1) % poly.size()];
      area += a.x() * b.y() - b.x() * a.y();
      if (a.x() < e_.u_start() - 1e-2 * du || a.x() > e_.u_end() + 1e-2 * du || a.y() < e_.v_start() - 1e-2 * dv ||
          a.y() > e_.v_end() + 1e-2 * dv)
        throw GeometryError(f_.name, "trimming loop " + std::to_string(index) + " leaves the surface's domain at (" +
                                         std::to_string(a.x()) + ", " + std::to_string(a.y()) + "), outside [" +
                                         std::to_string(e_.u_start()) + ", " + std::to_string(e_.u_end()) + "] x [" +
                                         std::to_string(e_.v_start()) + ", " + std::to_string(e_.v_end()) + "]");
    }
    if (std::abs(0.5 * area) <= 1e-12 * du * dv)
      throw GeometryError(f_.name, "trimming loop " + std::to_string(index) + " bounds no area");
  }

  Eigen::Vector2d inside_domain(const Eigen::Vector2d& uv) const {
    return {std::clamp(uv.x(), e_.u_start(), e_.u_end()), std::clamp(uv.y(), e_.v_start(), e_.v_end())};
  }

  static int index_at_or_below(const std::vector<double>& g, double x) {
    return static_cast<int>(std::upper_bound(g.begin(), g.end(), x) - g.begin()) - 1;
  }

  // -- 3. certification and refinement ----------------------------------------------------------
  // Exact for ids below 2^21 (two million vertices per face), a hash beyond.
  static std::uint64_t key(std::array<int, 3> t) {
    std::sort(t.begin(), t.end());
    const auto a = static_cast<std::uint64_t>(t[0]), b = static_cast<std::uint64_t>(t[1]), c = static_cast<std::uint64_t>(t[2]);
    if (c < (1u << 21)) return a | (b << 21) | (c << 42);
    return (1ull << 63) | ((a * 0x9E3779B97F4A7C15ull) ^ (b * 0xC2B2AE3D27D4EB4Full) ^ (c * 0x165667B19E3779F9ull));
  }

  // Pieces of the triangle between C0 knot lines, as barycentric corners (convex polygons, fanned).
  std::vector<std::array<Eigen::Vector3d, 3>> pieces(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                                      const Eigen::Vector2d& c, Verdict& v) const {
    std::vector<std::vector<Eigen::Vector3d>> polys{{Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1)}};
    auto at = [&](const Eigen::Vector3d& l) { return Eigen::Vector2d(l[0] * a + l[1] * b + l[2] * c); };
    double best_chord = -1;
    auto cut = [&](const std::vector<double>& lines, int axis) {
      const double lo = std::min({a[axis], b[axis], c[axis]}), hi = std::max({a[axis], b[axis], c[axis]});
      for (auto it = std::upper_bound(lines.begin(), lines.end(), lo); it != lines.end() && *it < hi; ++it) {
        const double x = *it;
        std::vector<std::vector<Eigen::Vector3d>> next;
        std::vector<Eigen::Vector3d> on_line;
        for (const auto& poly : polys) {
          std::vector<Eigen::Vector3d> left, right;
          for (size_t k = 0; k < poly.size(); ++k) {
            const Eigen::Vector3d& p = poly[k];
            const Eigen::Vector3d& q = poly[(k + 1) % poly.size()];
            const double fp = at(p)[axis] - x, fq = at(q)[axis] - x;
            if (fp <= 0) left.push_back(p);
            if (fp >= 0) right.push_back(p);
            if ((fp < 0 && fq > 0) || (fp > 0 && fq < 0)) {
              const Eigen::Vector3d m = p + (q - p) * (fp / (fp - fq));
              left.push_back(m), right.push_back(m), on_line.push_back(m);
            }
          }
          if (left.size() >= 3) next.push_back(left);
          if (right.size() >= 3) next.push_back(right);
        }
        polys = std::move(next);
        if (on_line.size() >= 2) {
          v.crosses_c0 = true;
          Eigen::Vector2d p0 = at(on_line.front()), p1 = p0;
          for (const auto& m : on_line) {
            const Eigen::Vector2d q = at(m);
            if ((q - p0).norm() > (p1 - p0).norm()) p1 = q;
          }
          if ((p1 - p0).norm() > best_chord) best_chord = (p1 - p0).norm(), v.c0_point = 0.5 * (p0 + p1);
        }
      }
    };
    cut(f_.bound.c0_u, 0);
    cut(f_.bound.c0_v, 1);
    std::vector<std::array<Eigen::Vector3d, 3>> out;
    for (const auto& poly : polys)
      for (size_t k = 1; k + 1 < poly.size(); ++k) out.push_back({poly[0], poly[k], poly[k + 1]});
    return out;
  }

  Verdict certify(const std::array<int, 3>& t) const {
    const Vertex& A = vertices_[t[0]];
    const Vertex& B = vertices_[t[1]];
    const Vertex& C = vertices_[t[2]];
    Verdict v;
    v.peak = (A.uv + B.uv + C.uv) / 3.0;
    for (int k = 0; k < 3; ++k) v.sampled = std::max(v.sampled, vertices_[t[k]].error.norm());
    // Distance to the triangle's plane (the chordal deviation): a point of the surface may lie over
    // a neighbouring triangle, which a distance to this triangle would count as error. A triangle
    // collapsed in 3D (at a pole) has no plane: distance to it (to its sides) then.
    const Eigen::Vector3d cross = (B.point - A.point).cross(C.point - A.point);
    const bool plane = cross.norm() > 1e-12 * (B.point - A.point).norm() * (C.point - A.point).norm() && cross.norm() > 0;
    const Eigen::Vector3d normal = plane ? Eigen::Vector3d(cross.normalized()) : Eigen::Vector3d::Zero();
    const auto parts = pieces(A.uv, B.uv, C.uv, v);
    double total = 0;
    for (const auto& piece : parts) {
      Eigen::Vector2d corner[3];
      for (int k = 0; k < 3; ++k) corner[k] = piece[k][0] * A.uv + piece[k][1] * B.uv + piece[k][2] * C.uv;
      const auto m = f_.bound.over(std::min({corner[0].x(), corner[1].x(), corner[2].x()}),
                                   std::max({corner[0].x(), corner[1].x(), corner[2].x()}),
                                   std::min({corner[0].y(), corner[1].y(), corner[2].y()}),
                                   std::max({corner[0].y(), corner[1].y(), corner[2].y()}));
      const double whole = triangle_deviation_bound(corner[0], corner[1], corner[2], m);
      // The rigorous bound alone may do (flat or nearly flat pieces): no sampling then.
      const double corner_error = parts.size() == 1 ? v.sampled : d_;
      if (corner_error + whole <= d_) {
        total = std::max(total, corner_error + whole);
        continue;
      }
      double bound = 0;
      for (int k = 3; k <= 12; k *= 2) {
        double sampled = 0;
        for (int i = 0; i <= k; ++i)
          for (int j = 0; i + j <= k; ++j) {
            const Eigen::Vector3d l = (piece[0] * (k - i - j) + piece[1] * i + piece[2] * j) / k;
            // Corners of the mesh triangle: cached error.
            int corner_index = -1;
            for (int q = 0; q < 3; ++q)
              if (l[q] == 1.0) corner_index = q;
            double err;
            if (corner_index >= 0) {
              err = vertices_[t[corner_index]].error.norm();
            } else {
              const Eigen::Vector2d uv = l[0] * A.uv + l[1] * B.uv + l[2] * C.uv;
              err = plane ? std::abs(normal.dot(e_.point(uv.x(), uv.y()) - A.point))
                          : point_triangle_distance(e_.point(uv.x(), uv.y()), A.point, B.point, C.point);
            }
            sampled = std::max(sampled, err);
            if (err >= v.sampled && corner_index < 0) {
              v.sampled = err;
              v.peak = l[0] * A.uv + l[1] * B.uv + l[2] * C.uv;
              v.edge = l[2] == 0 ? 0 : l[0] == 0 ? 1 : l[1] == 0 ? 2 : -1;
            }
          }
        bound = sampled + whole / (k * k);
        if (sampled > d_ || bound <= d_) break;
      }
      total = std::max(total, bound);
    }
    v.bound = total;
    v.ok = total <= d_;
    return v;
  }

  void refine() {
    // A budget, so that a triangle no refinement can certify (a loose bound at a pole) cannot make the
    // face grow without end: what is left above D then is reported as uncertified.
    const int budget = 64 * dt_->vertex_count() + 20000;
    for (int round = 0; round < 200 && dt_->vertex_count() < budget; ++round) {
      triangles_ = dt_->inside_triangles();
      const int before = dt_->vertex_count();
      std::vector<std::pair<Eigen::Vector2d, int>> inserts;  // point, a vertex of its triangle
      std::vector<std::pair<int, int>> splits;  // degenerate boundary edges to split
      std::unordered_set<std::uint64_t> edges_done;
      for (const auto& t : triangles_) {
        const std::uint64_t h = key(t);
        const std::optional<Verdict> failed = certify_once(t, h);
        if (!failed) continue;
        const Verdict& v = *failed;
        if (too_small(t)) {
          give_up(h, v);
          continue;
        }
        if (v.crosses_c0) {
          inserts.emplace_back(v.c0_point, t[0]);
          continue;
        }
        if (v.edge >= 0) {
          const int p = t[v.edge], q = t[(v.edge + 1) % 3];
          const std::uint64_t eh = (static_cast<std::uint64_t>(std::min(p, q)) << 32) | static_cast<std::uint32_t>(std::max(p, q));
          if (!dt_->is_constrained(p, q)) {
            if (edges_done.insert(eh).second) inserts.emplace_back(0.5 * (vertices_[p].uv + vertices_[q].uv), p);
            continue;
          }
          if (vertices_[p].node >= 0 && vertices_[p].node == vertices_[q].node) {
            if (edges_done.insert(eh).second) splits.emplace_back(p, q);
            continue;
          }
          // A real boundary edge that is itself too far off: nothing inside can fix it.
          if (v.sampled > d_) {
            give_up(h, v);
            continue;
          }
          inserts.emplace_back((vertices_[t[0]].uv + vertices_[t[1]].uv + vertices_[t[2]].uv) / 3.0, t[0]);
          continue;
        }
        inserts.emplace_back(v.peak, t[0]);
      }
      for (const auto& [p, q] : splits) {
        const Vertex pole = vertices_[p];
        const int m = dt_->split_constrained_edge(p, q, 0.5 * (vertices_[p].uv + vertices_[q].uv));
        sync_vertices();
        if (vertices_[m].node == -2) set_vertex(m, dt_->uv(m), pole.point, pole.node);
      }
      for (const auto& [uv, near] : inserts) {
        const int id = dt_->insert(uv, near);
        sync_vertices();
        if (vertices_[id].node == -2) set_vertex(id, uv, e_.point(uv.x(), uv.y()), -1);
      }
      for (auto& v : vertices_)
        if (v.node == -2) v.node = -1, v.error = Eigen::Vector3d::Zero();
      if (dt_->vertex_count() == before) break;
    }
    // Whatever is still above D (no progress, or too many rounds) is reported, not hidden.
    triangles_ = dt_->inside_triangles();
    for (const auto& t : triangles_) {
      const std::uint64_t h = key(t);
      if (const std::optional<Verdict> failed = certify_once(t, h)) give_up(h, *failed);
    }
  }

  // Certifies triangle t (hash h) unless it was already settled; the verdict when it fails.
  std::optional<Verdict> certify_once(const std::array<int, 3>& t, std::uint64_t h) {
    if (certified_.count(h)) return std::nullopt;
    const Verdict v = certify(t);
    if (!v.ok) return v;
    certified_.insert(h);
    report_.certified_deviation = std::max(report_.certified_deviation, v.bound);
    return std::nullopt;
  }

  bool too_small(const std::array<int, 3>& t) const {
    const double du = (us_.back() - us_.front()), dv = (vs_.back() - vs_.front());
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d d = vertices_[t[k]].uv - vertices_[t[(k + 1) % 3]].uv;
      if (std::abs(d.x()) > 1e-9 * du || std::abs(d.y()) > 1e-9 * dv) return false;
    }
    return true;
  }

  void give_up(std::uint64_t h, const Verdict& v) {
    certified_.insert(h);
    ++report_.uncertified_triangles;
    report_.certified_deviation = std::max(report_.certified_deviation, v.bound);
  }

  // -- 4. output --------------------------------------------------------------------------------
  void emit() {
    TriangleMesh& mesh = f_.mesh;
    std::unordered_map<int, int> by_node;
    std::vector<int> index(vertices_.size(), -1);
    auto mesh_index = [&](int id) {
      if (index[id] >= 0) return index[id];
      const Vertex& v = vertices_[id];
      if (v.node >= 0) {
        const auto [it, fresh] = by_node.emplace(v.node, static_cast<int>(mesh.positions.size()));
        if (fresh) mesh.positions.push_back(v.point);
        return index[id] = it->second;
      }
      mesh.positions.push_back(v.point);
      return index[id] = static_cast<int>(mesh.positions.size()) - 1;
    };
    std::vector<Eigen::Vector3d> normals(vertices_.size());
    std::vector<char> has_normal(vertices_.size(), 0);
    for (const auto& t : triangles_) {
      const std::array<int, 3> m{mesh_index(t[0]), mesh_index(t[1]), mesh_index(t[2])};
      if (m[0] == m[1] || m[1] == m[2] || m[2] == m[0]) continue;  // collapsed on a pole
      mesh.triangles.push_back(m);
      for (int k = 0; k < 3; ++k) {
        if (!has_normal[t[k]]) normals[t[k]] = normal_at(e_, vertices_[t[k]].uv), has_normal[t[k]] = 1;
        mesh.corner_normals.push_back(normals[t[k]]);
      }
    }
    report_.triangles += static_cast<long>(mesh.triangles.size());
  }
};

// ---------------------------------------------------------------------------------------------
// The whole job over a list of faces.

class Tessellator {
 public:
  Tessellator(std::vector<Face>& faces, double d, TessellationReport& report) : faces_(faces), d_(d), report_(report) {}

  void run() {
    for (auto& f : faces_) guarded(f, [&] { prepare(f); });
    find_degenerate_curves();
    join_vertices();
    for (size_t c = 0; c < curves_.size(); ++c) {
      if (curves_[c].uses.empty()) continue;  // a side replaced by its seam partner
      const CurveUse& first = curves_[c].uses.front();
      guarded(faces_[first.face], [&] { sample_curve(static_cast<int>(c)); });
    }
    // Coarse chords of nearby loops (a small hole near an outer boundary) may cross in (u,v), a
    // small closed edge may come out as fewer than 3 points, and a chord fine on the curve's first
    // face may be too coarse on another: split those chords on their curves, on every face that uses
    // them, until each face's loops are simple and each chord is fine on each face.
    // Only faces that use a split curve change between rounds (`stale`): the others keep their
    // points and have nothing to split.
    std::vector<char> stale(faces_.size(), 1);
    for (int round = 0;; ++round) {
      std::set<std::pair<int, int>> splits;
      for (size_t fi = 0; fi < faces_.size(); ++fi) {
        if (!stale[fi]) continue;
        guarded(faces_[fi], [&] { collect_loop_points(static_cast<int>(fi)); });
        chords_to_split(faces_[fi], splits);
        chords_too_coarse(faces_[fi], splits);
      }
      if (splits.empty() || round == 12) break;
      std::fill(stale.begin(), stale.end(), 0);
      for (auto it = splits.rbegin(); it != splits.rend(); ++it) {
        split_span(it->first, it->second);
        for (const CurveUse& use : curves_[it->first].uses) stale[use.face] = 1;
      }
    }
    for (auto& f : faces_) guarded(f, [&] { FaceMesher(f, d_, report_).run(); });
    report_.faces += static_cast<int>(faces_.size());
  }

 private:
  std::vector<Face>& faces_;
  double d_;
  TessellationReport& report_;
  std::vector<ModelCurve> curves_;
  // An edge id names one edge of one solid; a solid placed several times (assembly instances) has
  // several curves per edge, one per distinct world transform.
  std::map<std::pair<int, int>, int> curve_of_edge_;
  std::vector<Eigen::Matrix4d> placements_;
  UnionFind ends_;                    // 2 per curve: start, end
  std::vector<int> node_of_class_;    // vertex class root -> node id
  std::vector<Eigen::Vector3d> node_point_;
  std::vector<int> node_face_;        // face whose frame node_point_ is in

  template <class F>
  void guarded(Face& f, F&& work) {
    try {
      work();
    } catch (const GeometryError& e) {
      if (e.entity().rfind(f.name, 0) == 0) throw;
      throw GeometryError(f.name, e.what());
    } catch (const std::exception& e) {
      throw GeometryError(f.name, std::string("tessellation failed: ") + e.what());
    }
  }

  int new_curve() {
    curves_.emplace_back();
    ends_.add();
    ends_.add();
    return static_cast<int>(curves_.size()) - 1;
  }

  void prepare(Face& f) {
    validate(*f.trimmed, f.name);
    f.eval = std::make_unique<SurfaceEvaluator>(f.trimmed->surface);
    f.bound = surface_deviation_bound(f.trimmed->surface);
    const int fi = static_cast<int>(&f - faces_.data());
    if (f.trimmed->loops.empty()) {
      // The domain's sides; a closed direction's two sides are one curve (the seam).
      f.loops.push_back(domain_loop(f.trimmed->surface));
      const NurbsSurface& s = f.trimmed->surface;
      const Eigen::Vector2d a(s.u_start(), s.v_start()), b(s.u_end(), s.v_start()), c(s.u_end(), s.v_end()),
          d(s.u_start(), s.v_end());
      const double tol = std::min(1e-3 * d_, 1e-9 * std::max(1.0, control_net_size(s)) + 1e-3 * d_);
      std::vector<int> ids(4);
      for (int k = 0; k < 4; ++k) ids[k] = new_curve();
      std::vector<bool> rev(4, false);
      if (sides_coincide(*f.eval, b, c, a, d, tol)) ids[3] = ids[1], rev[3] = true;  // u sides: seam
      if (sides_coincide(*f.eval, a, b, d, c, tol)) ids[2] = ids[0], rev[2] = true;  // v sides
      f.curve.push_back(ids);
      f.reversed.push_back(rev);
    } else {
      f.loops = f.trimmed->loops;
      for (const auto& loop : f.loops) {
        std::vector<int> ids;
        std::vector<bool> rev;
        for (size_t k = 0; k < loop.segments.size(); ++k) {
          const TrimEdgeRef ref = loop.edges.empty() ? TrimEdgeRef{} : loop.edges[k];
          if (ref.edge < 0) {
            ids.push_back(new_curve());
            curves_.back().unnamed = true;
          } else {
            auto [it, fresh] = curve_of_edge_.emplace(std::pair{placement_of(f.world), ref.edge}, 0);
            if (fresh) it->second = new_curve();
            ids.push_back(it->second);
          }
          rev.push_back(ref.edge >= 0 && ref.reversed);
        }
        f.curve.push_back(ids);
        f.reversed.push_back(rev);
      }
    }
    std::vector<std::vector<Eigen::Vector2d>> polys;
    for (const auto& loop : f.loops) polys.push_back(loop_polygon(loop, 8));
    plan_grid(f, polys, d_);
    for (size_t l = 0; l < f.loops.size(); ++l)
      for (size_t k = 0; k < f.loops[l].segments.size(); ++k)
        curves_[f.curve[l][k]].uses.push_back({fi, static_cast<int>(l), static_cast<int>(k), static_cast<bool>(f.reversed[l][k])});
  }

  int placement_of(const Eigen::Affine3d& world) {
    for (size_t i = 0; i < placements_.size(); ++i)
      if (placements_[i] == world.matrix()) return static_cast<int>(i);
    placements_.push_back(world.matrix());
    return static_cast<int>(placements_.size()) - 1;
  }

  const TrimSegment& segment(const CurveUse& u) const { return faces_[u.face].loops[u.loop].segments[u.segment]; }

  void find_degenerate_curves() {
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
    for (auto& c : curves_) {
      if (c.uses.empty()) continue;
      const CurveUse& u = c.uses.front();
      // A gap closure shorter than D/2 is one vertex: sampled on its own it would leave a crack
      // beside the neighbouring face (Ventilator.stp). A loop made only of such segments closes no
      // gap: a small hole read back from a file that names no edges (11752.stp) stays a hole.
      const bool gap_closure = c.unnamed && !loop_is_tiny(u.face, u.loop);
      c.degenerate = is_degenerate_segment(*faces_[u.face].eval, segment(u), (gap_closure ? 0.5 : 1e-3) * d_);
    }
  }

  // End k (0 start, 1 end) of a segment use, as an index into ends_.
  int end_of(const CurveUse& u, int k) const {
    const int curve = faces_[u.face].curve[u.loop][u.segment];
    return 2 * curve + (u.reversed ? 1 - k : k);
  }

  void join_vertices() {
    for (size_t c = 0; c < curves_.size(); ++c)
      if (curves_[c].degenerate) ends_.unite(2 * static_cast<int>(c), 2 * static_cast<int>(c) + 1);
    for (size_t fi = 0; fi < faces_.size(); ++fi) {
      const Face& f = faces_[fi];
      for (size_t l = 0; l < f.loops.size(); ++l) {
        const int n = static_cast<int>(f.loops[l].segments.size());
        for (int k = 0; k < n; ++k) {
          const CurveUse a{static_cast<int>(fi), static_cast<int>(l), k, f.reversed[l][k]};
          const CurveUse b{static_cast<int>(fi), static_cast<int>(l), (k + 1) % n, f.reversed[l][(k + 1) % n]};
          ends_.unite(end_of(a, 1), end_of(b, 0));
        }
      }
    }
    // Node ids and positions of the vertex classes, from the first face that reaches them.
    node_of_class_.assign(ends_.parent.size(), -1);
    for (size_t c = 0; c < curves_.size(); ++c)
      for (const CurveUse& u : curves_[c].uses)
        for (int k = 0; k < 2; ++k) {
          const int root = ends_.find(end_of(u, k));
          if (node_of_class_[root] >= 0) continue;
          const TrimSegment& s = segment(u);
          const Eigen::Vector2d uv = segment_uv(s, k == 0 ? segment_t0(s) : segment_t1(s));
          node_of_class_[root] = add_node(faces_[u.face].eval->point(uv.x(), uv.y()), u.face);
        }
  }

  int add_node(const Eigen::Vector3d& p, int face) {
    node_point_.push_back(p);
    node_face_.push_back(face);
    return static_cast<int>(node_point_.size()) - 1;
  }

  // A node's position in the frame of `face` (the same bits when the frames are the same).
  Eigen::Vector3d node_in(int node, int face) const {
    const Eigen::Affine3d& from = faces_[node_face_[node]].world;
    const Eigen::Affine3d& to = faces_[face].world;
    if (from.matrix() == to.matrix()) return node_point_[node];
    return to.inverse() * (from * node_point_[node]);
  }

  int node_of_end(const CurveUse& u, int k) { return node_of_class_[ends_.find(end_of(u, k))]; }

  void sample_curve(int c) {
    ModelCurve& curve = curves_[c];
    if (curve.degenerate) return;
    const CurveUse& u = curve.uses.front();
    const Face& f = faces_[u.face];
    const int n0 = node_of_end(u, 0), n1 = node_of_end(u, 1);
    auto samples =
        sample_trim_segment(*f.eval, f.bound, segment(u), d_, node_in(n0, u.face), node_in(n1, u.face), &f.us, &f.vs);
    if (u.reversed) std::reverse(samples.begin(), samples.end());
    const int first_node = u.reversed ? n1 : n0, last_node = u.reversed ? n0 : n1;
    double length = 0;
    for (size_t k = 0; k < samples.size(); ++k) {
      if (k > 0) length += (samples[k].point - samples[k - 1].point).norm();
      curve.points.push_back(samples[k].point);
      curve.uvs.push_back(samples[k].uv);
      curve.ts.push_back(samples[k].t);
      curve.arc.push_back(length);
      curve.nodes.push_back(k == 0 ? first_node : k + 1 == samples.size() ? last_node : add_node(samples[k].point, u.face));
    }
    for (auto& a : curve.arc) a = length > 0 ? a / length : 0;
  }

  void collect_loop_points(int fi) {
    Face& f = faces_[fi];
    f.points.assign(f.loops.size(), {});
    for (size_t l = 0; l < f.loops.size(); ++l)
      for (size_t k = 0; k < f.loops[l].segments.size(); ++k) {
        const CurveUse use{fi, static_cast<int>(l), static_cast<int>(k), f.reversed[l][k]};
        append_use(f, use, f.points[l]);
      }
  }

  // Points of one segment use, start included, end excluded (it starts the next segment).
  void append_use(Face& f, const CurveUse& use, std::vector<LoopPoint>& out) {
    const TrimSegment& s = segment(use);
    const int curve_index = f.curve[use.loop][use.segment];
    const ModelCurve& curve = curves_[curve_index];
    const double t0 = segment_t0(s), t1 = segment_t1(s);
    const int start_node = node_of_end(use, 0);
    if (curve.degenerate) {
      out.push_back({segment_uv(s, t0), node_in(start_node, use.face), start_node, &s, t0, t1});
      return;
    }
    const CurveUse& origin = curve.uses.front();
    if (origin.face == use.face && origin.loop == use.loop && origin.segment == use.segment) {
      // Sampled here: the stored samples, in this segment's direction.
      const size_t n = curve.points.size();
      for (size_t k = 0; k + 1 < n; ++k) {
        const size_t i = use.reversed ? n - 1 - k : k;
        out.push_back({curve.uvs[i], curve.points[i], curve.nodes[i]});
        out.back().curve = curve_index;
        out.back().span = static_cast<int>(use.reversed ? i - 1 : i);
      }
      return;
    }
    if (!invert_use(f, use, s, curve, curve_index, out)) {
      ++report_.unshared_edge_uses;
      own_samples(f, s, out);
    }
  }

  // The shared samples located on this face; false when they do not lie on it within D.
  bool invert_use(Face& f, const CurveUse& use, const TrimSegment& s, const ModelCurve& curve, int curve_index,
                  std::vector<LoopPoint>& out) {
    const SurfaceEvaluator& e = *f.eval;
    const double t0 = segment_t0(s), t1 = segment_t1(s);
    const size_t n = curve.points.size();
    // Arc-length table of this segment's 3D image, for proportional starts.
    std::vector<double> ts, lengths{0.0};
    const auto breaks = segment_breaks(s);
    for (size_t i = 0; i + 1 < breaks.size(); ++i)
      for (int k = (i == 0 ? 0 : 1); k <= 16; ++k) ts.push_back(breaks[i] + (breaks[i + 1] - breaks[i]) * k / 16);
    Eigen::Vector3d prev = e.point(segment_uv(s, ts[0]).x(), segment_uv(s, ts[0]).y());
    for (size_t i = 1; i < ts.size(); ++i) {
      const Eigen::Vector2d uv = segment_uv(s, ts[i]);
      const Eigen::Vector3d p = e.point(uv.x(), uv.y());
      lengths.push_back(lengths.back() + (p - prev).norm());
      prev = p;
    }
    auto t_at = [&](double fraction) {
      const double target = fraction * lengths.back();
      const size_t i = std::min(ts.size() - 2, static_cast<size_t>(std::upper_bound(lengths.begin(), lengths.end(), target) -
                                                                   lengths.begin()) - (target > 0 ? 1 : 0));
      const double span = lengths[i + 1] - lengths[i];
      const double w = span > 0 ? std::clamp((target - lengths[i]) / span, 0.0, 1.0) : 0.0;
      return ts[i] + w * (ts[i + 1] - ts[i]);
    };
    std::vector<LoopPoint> mine;
    const int start_node = node_of_end(use, 0), end_node = node_of_end(use, 1);
    const Eigen::Vector2d start_uv = segment_uv(s, t0), end_uv = segment_uv(s, t1);
    const Eigen::Vector3d start_point = node_in(start_node, use.face), end_point = node_in(end_node, use.face);
    if ((e.point(start_uv.x(), start_uv.y()) - start_point).norm() > d_ ||
        (e.point(end_uv.x(), end_uv.y()) - end_point).norm() > d_)
      return false;
    mine.push_back({start_uv, start_point, start_node});
    mine.back().curve = curve_index;
    mine.back().span = static_cast<int>(use.reversed ? n - 2 : 0);
    double t_prev = t0;
    for (size_t k = 1; k + 1 < n; ++k) {
      const size_t i = use.reversed ? n - 1 - k : k;
      const double fraction = use.reversed ? 1 - curve.arc[i] : curve.arc[i];
      const Eigen::Vector3d p = node_in(curve.nodes[i], use.face);
      const CurveProjection on_curve = project_to_trim_curve(e, s, p, std::max(t_prev, t_at(fraction)), t_prev, t1);
      if (on_curve.distance > d_) return false;
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
      mine.back().curve = curve_index;
      mine.back().span = static_cast<int>(use.reversed ? i - 1 : i);
    }
    out.insert(out.end(), mine.begin(), mine.end());
    return true;
  }

  // Splittable chords (curve, span) of face f that cross another chord of its loops, or that belong
  // to a loop of fewer than 3 distinct points.
  void chords_to_split(const Face& f, std::set<std::pair<int, int>>& out) const {
    struct Chord {
      Eigen::Vector2d a, b;
      int curve, span;
    };
    std::vector<Chord> chords;
    Eigen::AlignedBox2d box;
    for (const auto& loop : f.points) {
      std::vector<Eigen::Vector2d> distinct;
      for (size_t k = 0; k < loop.size(); ++k) {
        const LoopPoint& p = loop[k];
        const Eigen::Vector2d& q = loop[(k + 1) % loop.size()].uv;
        box.extend(p.uv);
        // Three distinct points are enough to know: no quadratic search on long loops.
        if (distinct.size() < 3 &&
            std::none_of(distinct.begin(), distinct.end(), [&](const Eigen::Vector2d& x) { return x == p.uv; }))
          distinct.push_back(p.uv);
        if (p.uv != q) chords.push_back({p.uv, q, p.curve, p.span});
      }
      if (distinct.size() < 3)
        for (const auto& p : loop)
          if (p.curve >= 0) out.emplace(p.curve, p.span);
    }
    if (chords.size() < 2) return;
    // Buckets of a uniform grid over the loops' box; pairs are tested within a bucket.
    const int n = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(chords.size()))), 1, 256);
    const Eigen::Vector2d lo = box.min(), size = (box.max() - box.min()).cwiseMax(1e-300);
    auto cell = [&](double x, double extent, double origin) {
      return std::clamp(static_cast<int>((x - origin) / extent * n), 0, n - 1);
    };
    std::vector<std::vector<int>> buckets(static_cast<size_t>(n) * n);
    for (size_t c = 0; c < chords.size(); ++c) {
      const Chord& h = chords[c];
      const int i0 = cell(std::min(h.a.x(), h.b.x()), size.x(), lo.x()), i1 = cell(std::max(h.a.x(), h.b.x()), size.x(), lo.x());
      const int j0 = cell(std::min(h.a.y(), h.b.y()), size.y(), lo.y()), j1 = cell(std::max(h.a.y(), h.b.y()), size.y(), lo.y());
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) buckets[i + j * n].push_back(static_cast<int>(c));
    }
    auto side = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r) {
      const double x = (q - p).x() * (r - p).y() - (q - p).y() * (r - p).x();
      return (x > 0) - (x < 0);
    };
    for (const auto& bucket : buckets)
      for (size_t x = 0; x < bucket.size(); ++x)
        for (size_t y = x + 1; y < bucket.size(); ++y) {
          const Chord& p = chords[bucket[x]];
          const Chord& q = chords[bucket[y]];
          if (p.a == q.a || p.a == q.b || p.b == q.a || p.b == q.b) continue;  // neighbours
          // Proper crossings only: chords that touch or overlap follow loops that touch or overlap
          // themselves in the file (Ventilator.stp), which no split can undo; CGAL joins those
          // constraints without new vertices.
          if (side(p.a, p.b, q.a) * side(p.a, p.b, q.b) >= 0 || side(q.a, q.b, p.a) * side(q.a, q.b, p.b) >= 0) continue;
          if (p.curve >= 0) out.emplace(p.curve, p.span);
          if (q.curve >= 0) out.emplace(q.curve, q.span);
        }
  }

  // Splittable chords of face f that its surface does not follow within D (criterion (2) of
  // sample_trim_segment, between this face's own points at the chord's ends), or that cross more
  // than one line of its grid. A curve is sampled on its first face; on the others, triangles along
  // such a chord could never be certified, and refining towards it only makes slivers.
  void chords_too_coarse(const Face& f, std::set<std::pair<int, int>>& out) const {
    for (const auto& loop : f.points) {
      std::vector<Eigen::Vector3d> on_face(loop.size());  // this face's points at the loop's (u,v)
      for (size_t k = 0; k < loop.size(); ++k) on_face[k] = f.eval->point(loop[k].uv.x(), loop[k].uv.y());
      for (size_t k = 0; k < loop.size(); ++k) {
        const LoopPoint& p = loop[k];
        if (p.curve < 0) continue;
        const size_t next = (k + 1) % loop.size();
        const Eigen::Vector2d& a = p.uv;
        const Eigen::Vector2d& b = loop[next].uv;
        if (lines_between(f.us, a.x(), b.x()) > 1 || lines_between(f.vs, a.y(), b.y()) > 1 ||
            !surface_chord_within(*f.eval, f.bound, a, on_face[k], b, on_face[next], d_))
          out.emplace(p.curve, p.span);
      }
    }
  }

  // A new sample in the middle (in the origin segment's parameter) of span `span` of curve c.
  void split_span(int c, int span) {
    ModelCurve& curve = curves_[c];
    const CurveUse& u = curve.uses.front();
    const TrimSegment& s = segment(u);
    const double t = 0.5 * (curve.ts[span] + curve.ts[span + 1]);
    const Eigen::Vector2d uv = segment_uv(s, t);
    const Eigen::Vector3d p = faces_[u.face].eval->point(uv.x(), uv.y());
    const auto at = static_cast<std::ptrdiff_t>(span + 1);
    curve.points.insert(curve.points.begin() + at, p);
    curve.uvs.insert(curve.uvs.begin() + at, uv);
    curve.ts.insert(curve.ts.begin() + at, t);
    curve.nodes.insert(curve.nodes.begin() + at, add_node(p, u.face));
    curve.arc.assign(1, 0.0);
    for (size_t k = 1; k < curve.points.size(); ++k) curve.arc.push_back(curve.arc.back() + (curve.points[k] - curve.points[k - 1]).norm());
    for (auto& a : curve.arc) a = curve.arc.back() > 0 ? a / curve.arc.back() : 0;
  }

  void own_samples(Face& f, const TrimSegment& s, std::vector<LoopPoint>& out) {
    const Eigen::Vector2d a = segment_uv(s, segment_t0(s)), b = segment_uv(s, segment_t1(s));
    const Eigen::Vector3d pa = f.eval->point(a.x(), a.y()), pb = f.eval->point(b.x(), b.y());
    const auto samples = sample_trim_segment(*f.eval, f.bound, s, d_, pa, pb, &f.us, &f.vs);
    for (size_t k = 0; k + 1 < samples.size(); ++k)
      out.push_back({samples[k].uv, samples[k].point, add_node(samples[k].point, static_cast<int>(&f - faces_.data()))});
  }
};

void check_deviation(double d) {
  if (!(d > 0) || !std::isfinite(d))
    throw GeometryError("tessellate_to_deviation", "the maximum deviation must be a positive number, not " + std::to_string(d));
}

void collect_faces(SceneNode& node, const std::string& path, const Eigen::Affine3d& parent, std::vector<Face>& faces,
                   std::vector<Shape*>& shapes) {
  const Eigen::Affine3d world = parent * node.transform;
  for (size_t i = 0; i < node.shapes.size(); ++i) {
    Shape& shape = node.shapes[i];
    const auto* t = std::get_if<TrimmedSurface>(&shape.geometry);
    if (!t) continue;
    Face f;
    f.trimmed = t;
    f.name = path + "/" + (display_name(shape).empty() ? "shape " + std::to_string(i) : display_name(shape));
    f.world = world;
    faces.push_back(std::move(f));
    shapes.push_back(&shape);
  }
  for (auto& child : node.children) collect_faces(child, path + "/" + display_name(child), world, faces, shapes);
}

}  // namespace

TriangleMesh tessellate_to_deviation(const TrimmedSurface& surface, double max_deviation, TessellationReport* report) {
  check_deviation(max_deviation);
  TessellationReport local;
  std::vector<Face> faces(1);
  faces[0].trimmed = &surface;
  faces[0].name = "surface";
  Tessellator(faces, max_deviation, report ? *report : local).run();
  return std::move(faces[0].mesh);
}

Scene tessellate_to_deviation(const Scene& scene, double max_deviation, TessellationReport* report) {
  check_deviation(max_deviation);
  TessellationReport local;
  Scene out = scene;
  std::vector<Face> faces;
  std::vector<Shape*> shapes;
  collect_faces(out.root, out.root.name, Eigen::Affine3d::Identity(), faces, shapes);
  Tessellator(faces, max_deviation, report ? *report : local).run();
  for (size_t i = 0; i < faces.size(); ++i) shapes[i]->geometry = std::move(faces[i].mesh);
  return out;
}

}  // namespace cadnurbs
