#include "analysis/tessellation/face_meshing.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "analysis/tessellation/domain_triangulation.hpp"
#include "analysis/eval/sample_trim_segment.hpp"
#include "analysis/tessellation/segment_meets_box.hpp"
#include "analysis/tessellation/surface_normal.hpp"
#include "analysis/tessellation/surface_point_cache.hpp"
#include "analysis/tessellation/triangle_certification.hpp"
#include "core/geometry_error.hpp"
#include "core/point_in_loops.hpp"
#include "core/polygon_2d.hpp"

namespace cadnurbs::tessellation {

namespace {

// What a triangulation vertex stands for.
enum class VertexOrigin {
  pending,  // made by the triangulation (an insertion or a constraint crossing), not described yet
  own,      // a vertex of this face alone: a grid point, a refinement point, a constraint crossing
  model,    // a loop point: the vertex of its model node, the same 3D point on every face using it
};

struct Vertex : MeshCorner {
  VertexOrigin origin = VertexOrigin::pending;
  NodeId node;  // when origin is model
};

// Exact for ids below 2^21 (two million vertices per face), a hash beyond.
std::uint64_t triangle_key(std::array<int, 3> t) {
  std::sort(t.begin(), t.end());
  const auto a = static_cast<std::uint64_t>(t[0]), b = static_cast<std::uint64_t>(t[1]), c = static_cast<std::uint64_t>(t[2]);
  if (c < (1u << 21)) return a | (b << 21) | (c << 42);
  return (1ull << 63) | ((a * 0x9E3779B97F4A7C15ull) ^ (b * 0xC2B2AE3D27D4EB4Full) ^ (c * 0x165667B19E3779F9ull));
}

int index_at_or_below(const std::vector<double>& g, double x) {
  return static_cast<int>(std::upper_bound(g.begin(), g.end(), x) - g.begin()) - 1;
}

class FaceMesher {
 public:
  FaceMesher(Face& face, double d, TessellationReport& report)
      : f_(face), e_(*face.eval), points_(*face.eval, face.us.size() * face.vs.size()), d_(d), report_(report) {}

  void run() {
    us_ = f_.us;
    vs_ = f_.vs;
    if (!build_triangulation()) return;  // no loop bounds area at D: the face has no triangles
    refine();
    emit();
  }

 private:
  Face& f_;
  const SurfaceEvaluator& e_;
  SurfacePointCache points_;  // every point of the surface this face asks for, evaluated once
  double d_;
  TessellationReport& report_;
  std::vector<double> us_, vs_;  // grid parameters (knots included)
  std::unique_ptr<DomainTriangulation> dt_;
  std::vector<Vertex> vertices_;
  std::unordered_set<std::uint64_t> certified_;  // keys of settled triangles (certified or given up)
  std::vector<std::array<int, 3>> triangles_;

  // -- 3. triangulation -------------------------------------------------------------------------
  // Inserts uv; a vertex new to the triangulation becomes `point` (a model node's vertex when `node`
  // is given, else one of this face's own). Returns the vertex id.
  int add_vertex(const Eigen::Vector2d& uv, const Eigen::Vector3d& point, std::optional<NodeId> node) {
    const int id = dt_->insert(uv);
    sync_vertices();
    if (id == static_cast<int>(vertices_.size()) - 1 && vertices_[id].origin == VertexOrigin::pending)
      set_vertex(id, uv, point, node);
    return id;
  }

  void set_vertex(int id, const Eigen::Vector2d& uv, const Eigen::Vector3d& point, std::optional<NodeId> node) {
    Vertex& v = vertices_[id];
    v.uv = uv, v.point = point, v.error = points_.point(uv.x(), uv.y()) - point;
    v.origin = node ? VertexOrigin::model : VertexOrigin::own;
    v.node = node.value_or(NodeId{});
  }

  // New triangulation vertices (insertions, constraint crossings) get pending records first.
  void sync_vertices() {
    while (static_cast<int>(vertices_.size()) < dt_->vertex_count()) {
      const int id = static_cast<int>(vertices_.size());
      const Eigen::Vector2d uv = dt_->uv(id);
      Vertex v;
      v.uv = uv, v.point = points_.point(uv.x(), uv.y()), v.error = Eigen::Vector3d::Zero();
      vertices_.push_back(v);
    }
  }

  // Pending vertices (the triangulation's own) become this face's own, on the surface.
  void settle_pending() {
    for (auto& v : vertices_)
      if (v.origin == VertexOrigin::pending) v.origin = VertexOrigin::own, v.error = Eigen::Vector3d::Zero();
  }

  // False when no loop bounds any area as sampled at D: the face is then thinner than D, within D of
  // its boundary's chords, which its neighbours' meshes hold.
  bool build_triangulation() {
    const double su = (us_.size() - 1) / (us_.back() - us_.front());
    const double sv = (vs_.size() - 1) / (vs_.back() - vs_.front());
    dt_ = std::make_unique<DomainTriangulation>(su, sv);
    // Loops first, with degenerate runs split to the grid's resolution.
    std::vector<std::vector<Eigen::Vector2d>> polys;
    for (size_t l = 0; l < f_.points.size(); ++l) {
      const auto& loop = f_.points[l];
      std::vector<Eigen::Vector2d> given;
      for (const LoopPoint& p : loop) given.push_back(p.uv);
      if (!check_loop(given, l)) {
        ++report_.loops_without_area;
        continue;
      }
      std::vector<int> ids;
      std::vector<Eigen::Vector2d> poly;
      for (size_t k = 0; k < loop.size(); ++k) {
        const LoopPoint& p = loop[k];
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
      dt_->insert_loop(ids);
      sync_vertices();
      polys.push_back(std::move(poly));
    }
    if (polys.empty() && !f_.points.empty()) return false;
    settle_pending();  // constraint crossings
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
        add_vertex(uv, points_.point(uv.x(), uv.y()), std::nullopt);
      }
    }
    return true;
  }

  // Refuses loops that leave the surface's domain by more than 1e-2 of it. Files put pcurves a little
  // outside (11752.stp: 1.5e-3 of a B-spline's domain); their points are moved onto the domain's edge
  // (inside_domain), where the surface is clamped anyway. False for a loop that bounds no area as
  // sampled at D (a sliver the reader's finer samples kept): like the repair's, it trims nothing.
  bool check_loop(const std::vector<Eigen::Vector2d>& poly, size_t index) const {
    const double du = e_.u_end() - e_.u_start(), dv = e_.v_end() - e_.v_start();
    for (const Eigen::Vector2d& a : poly)
      if (a.x() < e_.u_start() - 1e-2 * du || a.x() > e_.u_end() + 1e-2 * du || a.y() < e_.v_start() - 1e-2 * dv ||
          a.y() > e_.v_end() + 1e-2 * dv)
        throw GeometryError(f_.name, "trimming loop " + std::to_string(index) + " leaves the surface's domain at (" +
                                         std::to_string(a.x()) + ", " + std::to_string(a.y()) + "), outside [" +
                                         std::to_string(e_.u_start()) + ", " + std::to_string(e_.u_end()) + "] x [" +
                                         std::to_string(e_.v_start()) + ", " + std::to_string(e_.v_end()) + "]");
    return std::abs(polygon_signed_area(poly)) > 1e-12 * du * dv;
  }

  Eigen::Vector2d inside_domain(const Eigen::Vector2d& uv) const {
    return {std::clamp(uv.x(), e_.u_start(), e_.u_end()), std::clamp(uv.y(), e_.v_start(), e_.v_end())};
  }

  // -- 4. certification and refinement ----------------------------------------------------------
  bool same_model_node(int p, int q) const {
    return vertices_[p].origin == VertexOrigin::model && vertices_[q].origin == VertexOrigin::model &&
           vertices_[p].node == vertices_[q].node;
  }

  void refine() {
    // A budget, so that a triangle no refinement can certify (a loose bound at a pole) cannot make the
    // face grow without end: what is left above D then is reported as uncertified.
    const int budget = 64 * dt_->vertex_count() + 20000;
    for (int round = 0; round < 200 && dt_->vertex_count() < budget; ++round) {
      triangles_ = dt_->inside_triangles();
      const int before = dt_->vertex_count();
      std::vector<std::pair<Eigen::Vector2d, int>> inserts;  // point, a vertex of its triangle
      std::vector<std::pair<int, int>> splits;               // collapsed boundary sides to split
      std::unordered_set<std::uint64_t> sides_done;
      for (const auto& t : triangles_) {
        const std::uint64_t h = triangle_key(t);
        const std::optional<TriangleVerdict> failed = certify_once(t, h);
        if (!failed) continue;
        const TriangleVerdict& v = *failed;
        if (too_small(t)) {
          give_up(h, v);
          continue;
        }
        if (v.crosses_c0) {
          inserts.emplace_back(v.c0_point, t[0]);
          continue;
        }
        if (v.peak_side) {
          const int p = t[*v.peak_side], q = t[(*v.peak_side + 1) % 3];
          const std::uint64_t side_key = (static_cast<std::uint64_t>(std::min(p, q)) << 32) | static_cast<std::uint32_t>(std::max(p, q));
          if (!dt_->is_constrained(p, q)) {
            if (sides_done.insert(side_key).second) inserts.emplace_back(0.5 * (vertices_[p].uv + vertices_[q].uv), p);
            continue;
          }
          if (same_model_node(p, q)) {
            if (sides_done.insert(side_key).second) splits.emplace_back(p, q);
            continue;
          }
          // A real boundary side that is itself too far off: nothing inside can fix it.
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
        if (vertices_[m].origin == VertexOrigin::pending) set_vertex(m, dt_->uv(m), pole.point, pole.node);
      }
      for (const auto& [uv, near] : inserts) {
        const int id = dt_->insert(uv, near);
        sync_vertices();
        if (vertices_[id].origin == VertexOrigin::pending) set_vertex(id, uv, points_.point(uv.x(), uv.y()), std::nullopt);
      }
      settle_pending();
      if (dt_->vertex_count() == before) break;
    }
    // Whatever is still above D (no progress, or too many rounds) is reported, not hidden.
    triangles_ = dt_->inside_triangles();
    for (const auto& t : triangles_) {
      const std::uint64_t h = triangle_key(t);
      if (const std::optional<TriangleVerdict> failed = certify_once(t, h)) give_up(h, *failed);
    }
  }

  // Certifies triangle t (key h) unless it was already settled; the verdict when it fails.
  std::optional<TriangleVerdict> certify_once(const std::array<int, 3>& t, std::uint64_t h) {
    if (certified_.count(h)) return std::nullopt;
    const TriangleVerdict v = certify_triangle(points_, f_.bound, vertices_[t[0]], vertices_[t[1]], vertices_[t[2]], d_);
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

  void give_up(std::uint64_t h, const TriangleVerdict& v) {
    certified_.insert(h);
    ++report_.uncertified_triangles;
    report_.certified_deviation = std::max(report_.certified_deviation, v.bound);
  }

  // -- 5. output --------------------------------------------------------------------------------
  void emit() {
    TriangleMesh& mesh = f_.mesh;
    std::unordered_map<int, int> by_node;  // model node index -> mesh vertex
    std::vector<int> index(vertices_.size(), -1);
    auto mesh_index = [&](int id) {
      if (index[id] >= 0) return index[id];
      const Vertex& v = vertices_[id];
      if (v.origin == VertexOrigin::model) {
        const auto [it, fresh] = by_node.emplace(v.node.index, static_cast<int>(mesh.positions.size()));
        if (fresh) mesh.positions.push_back(v.point);
        return index[id] = it->second;
      }
      mesh.positions.push_back(v.point);
      return index[id] = static_cast<int>(mesh.positions.size()) - 1;
    };
    std::vector<Eigen::Vector3d> normals(vertices_.size());
    std::vector<char> normal_done(vertices_.size(), 0);
    for (const auto& t : triangles_) {
      const std::array<int, 3> m{mesh_index(t[0]), mesh_index(t[1]), mesh_index(t[2])};
      if (m[0] == m[1] || m[1] == m[2] || m[2] == m[0]) continue;  // collapsed on a pole
      mesh.triangles.push_back(m);
      for (int k = 0; k < 3; ++k) {
        if (!normal_done[t[k]]) normals[t[k]] = normal_at(e_, vertices_[t[k]].uv), normal_done[t[k]] = 1;
        mesh.corner_normals.push_back(normals[t[k]]);
      }
    }
    report_.triangles += static_cast<long>(mesh.triangles.size());
  }
};

}  // namespace

void mesh_face(Face& face, double max_deviation, TessellationReport& report) {
  FaceMesher(face, max_deviation, report).run();
}

}  // namespace cadnurbs::tessellation
