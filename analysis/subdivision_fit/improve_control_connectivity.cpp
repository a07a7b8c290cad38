#include "analysis/subdivision_fit/improve_control_connectivity.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

#include "analysis/subdivision_fit/limit_patches.hpp"
#include "analysis/subdivision_fit/triangle_projection.hpp"
#include "analysis/mesh/sample_triangles.hpp"
#include "analysis/subdivision/limit_surface.hpp"

namespace cadnurbs {

namespace {

using namespace subdivision_fit;  // the closest-point helpers this file shares with the fit

// The input as data: sample points (as the distance measure takes them) with the normal of the input
// face each lies on, and an AABB tree for the other direction.
struct InputData {
  std::vector<K::Triangle_3> triangles;
  std::vector<Eigen::Vector3d> face_normals;
  TriangleTree tree;
  std::vector<Eigen::Vector3d> points, normals;
};

// A candidate control mesh and the triangles at each of its vertices (for regions and rings).
struct Candidate {
  SubdivisionControlMesh mesh;
  std::vector<std::vector<int>> vertex_triangles;
};

Candidate make_candidate(SubdivisionControlMesh mesh) {
  Candidate c;
  c.vertex_triangles.assign(mesh.positions.size(), {});
  for (size_t t = 0; t < mesh.triangles.size(); ++t)
    for (const int v : mesh.triangles[t]) c.vertex_triangles[v].push_back(static_cast<int>(t));
  c.mesh = std::move(mesh);
  return c;
}

// Vertices within `rings` edges of `seed`.
std::set<int> grow(const Candidate& c, std::set<int> seed, int rings) {
  for (int r = 0; r < rings; ++r) {
    std::set<int> next = seed;
    for (const int v : seed)
      for (const int t : c.vertex_triangles[v])
        for (const int u : c.mesh.triangles[t]) next.insert(u);
    seed = std::move(next);
  }
  return seed;
}

// One correspondence of the local least squares: a point of the limit surface as weights over control
// points, where it should be, and the normal of the plane it is measured against.
struct Pair {
  std::vector<std::pair<int, double>> stencil;
  Eigen::Vector3d target, normal;
};

class LocalFit {
 public:
  LocalFit(const InputData& input, const ConnectivityOptions& options, double spring_weight)
      : input_(input), options_(options), spring_weight_(spring_weight) {}

  // The local energy of `c` with its positions over `region` (control triangles) for the data points
  // `data`; with `free` non-empty, first re-fits those control points (others fixed) and writes them
  // into c.mesh.positions. Returns the energy; `feet` receives each data point's control triangle.
  double energy(Candidate& c, const std::vector<int>& region, const std::vector<int>& data, const std::vector<int>& free,
                std::vector<int>* feet) const {
    const int per_triangle = 1 << (2 * options_.levels);
    // The region's limit patches from its own 1-ring: the map does not change with the positions.
    const LimitPatches patches = limit_patches(control_mesh_topology(c.mesh), c.vertex_triangles, region, options_.levels);
    const LimitStencils& map = patches.limit_from_control;
    double e = 0;
    for (int round = 0; round <= (free.empty() ? 0 : options_.local_rounds); ++round) {
      // Limit triangles of the region at the current positions.
      std::vector<Eigen::Vector3d> limit_points(static_cast<size_t>(map.rows()), Eigen::Vector3d::Zero());
      for (long v = 0; v < map.rows(); ++v)
        for (LimitStencils::InnerIterator s(map, v); s; ++s) limit_points[v] += s.value() * c.mesh.positions[s.col()];
      std::vector<K::Triangle_3> triangles;
      triangles.reserve(patches.triangles.size());
      for (const auto& tri : patches.triangles)
        triangles.emplace_back(cg(limit_points[tri[0]]), cg(limit_points[tri[1]]), cg(limit_points[tri[2]]));
      TriangleTree tree(triangles.begin(), triangles.end());
      tree.accelerate_distance_queries();

      std::vector<Pair> pairs;
      e = 0;
      if (feet) feet->assign(data.size(), -1);
      for (size_t i = 0; i < data.size(); ++i) {
        const Eigen::Vector3d& x = input_.points[data[i]];
        const auto [foot, primitive] = tree.closest_point_and_primitive(cg(x));
        const size_t k = static_cast<size_t>(primitive - triangles.begin());
        if (feet) (*feet)[i] = region[k / per_triangle];
        e += (eig(foot) - x).squaredNorm();
        const auto& tri = patches.triangles[k];
        const Eigen::Vector3d& a = limit_points[tri[0]];
        const Eigen::Vector3d& b = limit_points[tri[1]];
        const Eigen::Vector3d& d = limit_points[tri[2]];
        Pair p;
        const Eigen::Vector3d bary = barycentric(eig(foot), a, b, d);
        for (int j = 0; j < 3; ++j)
          for (LimitStencils::InnerIterator s(map, tri[j]); s; ++s)
            p.stencil.emplace_back(static_cast<int>(s.col()), bary[j] * s.value());
        p.target = x;
        p.normal = unit_normal(a, b, d);
        if (p.normal.dot(input_.normals[data[i]]) >= 0) pairs.push_back(std::move(p));
      }
      // The other way: each limit triangle's centroid to the input (the same count for every
      // connectivity of the region, so energies compare).
      for (const auto& tri : patches.triangles) {
        const Eigen::Vector3d& a = limit_points[tri[0]];
        const Eigen::Vector3d& b = limit_points[tri[1]];
        const Eigen::Vector3d& d = limit_points[tri[2]];
        const Eigen::Vector3d centroid = (a + b + d) / 3;
        const auto [foot, primitive] = input_.tree.closest_point_and_primitive(cg(centroid));
        e += (eig(foot) - centroid).squaredNorm();
        Pair p;
        for (int m = 0; m < 3; ++m)
          for (LimitStencils::InnerIterator s(map, tri[m]); s; ++s)
            p.stencil.emplace_back(static_cast<int>(s.col()), s.value() / 3);
        p.target = eig(foot);
        p.normal = input_.face_normals[static_cast<size_t>(primitive - input_.triangles.begin())];
        const Eigen::Vector3d surface_normal = unit_normal(a, b, d);
        if (p.normal.dot(surface_normal) >= 0) pairs.push_back(std::move(p));
      }
      e += spring_weight_ * spring_energy(c, region_vertices(c, region));
      if (free.empty() || round == options_.local_rounds) break;
      solve(c, pairs, free);
    }
    return e;
  }

 private:
  std::vector<int> region_vertices(const Candidate& c, const std::vector<int>& region) const {
    std::set<int> v;
    for (const int t : region)
      for (const int u : c.mesh.triangles[t]) v.insert(u);
    return {v.begin(), v.end()};
  }

  // Sum over the edges at `vertices` of their squared length.
  double spring_energy(const Candidate& c, const std::vector<int>& vertices) const {
    std::set<std::pair<int, int>> edges;
    for (const int v : vertices)
      for (const int t : c.vertex_triangles[v])
        for (const int u : c.mesh.triangles[t])
          if (u != v) edges.insert({std::min(u, v), std::max(u, v)});
    double e = 0;
    for (const auto& [a, b] : edges) e += (c.mesh.positions[a] - c.mesh.positions[b]).squaredNorm();
    return e;
  }

  void solve(Candidate& c, const std::vector<Pair>& pairs, const std::vector<int>& free) const {
    std::map<int, int> column;
    for (const int v : free) column.emplace(v, static_cast<int>(column.size()));
    const long n = 3 * static_cast<long>(free.size());
    Eigen::MatrixXd ata = Eigen::MatrixXd::Zero(n, n);
    Eigen::VectorXd atb = Eigen::VectorXd::Zero(n);
    const double root = std::sqrt(options_.tangent_weight);
    std::vector<std::pair<int, double>> mine;
    for (const Pair& p : pairs) {
      mine.clear();
      Eigen::Vector3d fixed = Eigen::Vector3d::Zero();
      for (const auto& [v, w] : p.stencil) {
        const auto it = column.find(v);
        if (it == column.end()) fixed += w * c.mesh.positions[v];
        else mine.emplace_back(it->second, w);
      }
      if (mine.empty()) continue;
      // Plane row: n . (sum w x + fixed - target); point rows: root (sum w x + fixed - target).
      const double plane_rhs = p.normal.dot(p.target - fixed);
      const Eigen::Vector3d point_rhs = root * (p.target - fixed);
      for (const auto& [i, wi] : mine)
        for (const auto& [j, wj] : mine)
          for (int a = 0; a < 3; ++a) {
            for (int b = 0; b < 3; ++b) ata(3 * i + a, 3 * j + b) += wi * wj * p.normal[a] * p.normal[b];
            ata(3 * i + a, 3 * j + a) += root * root * wi * wj;
          }
      for (const auto& [i, wi] : mine)
        for (int a = 0; a < 3; ++a) atb(3 * i + a) += wi * (p.normal[a] * plane_rhs + root * point_rhs[a]);
    }
    // Springs on the edges at the free vertices.
    std::set<std::pair<int, int>> edges;
    for (const int v : free)
      for (const int t : c.vertex_triangles[v])
        for (const int u : c.mesh.triangles[t])
          if (u != v) edges.insert({std::min(u, v), std::max(u, v)});
    for (const auto& [a, b] : edges) {
      const auto ia = column.find(a), ib = column.find(b);
      for (int k = 0; k < 3; ++k) {
        if (ia != column.end()) ata(3 * ia->second + k, 3 * ia->second + k) += spring_weight_;
        if (ib != column.end()) ata(3 * ib->second + k, 3 * ib->second + k) += spring_weight_;
        if (ia != column.end() && ib != column.end()) {
          ata(3 * ia->second + k, 3 * ib->second + k) -= spring_weight_;
          ata(3 * ib->second + k, 3 * ia->second + k) -= spring_weight_;
        } else if (ia != column.end()) {
          atb(3 * ia->second + k) += spring_weight_ * c.mesh.positions[b][k];
        } else if (ib != column.end()) {
          atb(3 * ib->second + k) += spring_weight_ * c.mesh.positions[a][k];
        }
      }
    }
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(ata);
    if (ldlt.info() != Eigen::Success) return;
    const Eigen::VectorXd x = ldlt.solve(atb);
    if (!x.allFinite()) return;
    for (const auto& [v, i] : column) c.mesh.positions[v] = x.segment<3>(3 * i);
  }

  const InputData& input_;
  const ConnectivityOptions& options_;
  double spring_weight_;
};

// A move: the candidate mesh and the vertices whose connectivity or tags it changes.
struct Move {
  SubdivisionControlMesh mesh;
  std::set<int> changed;
};

}  // namespace

SubdivisionControlMesh improve_control_connectivity(const TriangleMesh& input_mesh, const SubdivisionControlMesh& fitted,
                                             const ConnectivityOptions& options, ConnectivityReport* report) {
  if (input_mesh.triangles.empty()) throw std::invalid_argument("improve_control_connectivity: the input has no triangles");
  if (fitted.triangles.empty()) throw std::invalid_argument("improve_control_connectivity: the control mesh has no triangles");
  if (options.levels < 1 || options.levels > 5)
    throw std::invalid_argument("improve_control_connectivity: levels must be 1 to 5");
  InputData input;
  for (const auto& t : input_mesh.triangles) {
    const auto& p = input_mesh.positions;
    input.triangles.emplace_back(cg(p[t[0]]), cg(p[t[1]]), cg(p[t[2]]));
    input.face_normals.push_back(unit_normal(p[t[0]], p[t[1]], p[t[2]]));
  }
  input.tree.insert(input.triangles.begin(), input.triangles.end());
  input.tree.accelerate_distance_queries();
  for (const Eigen::Vector3d& x : sample_triangles(input_mesh, default_sample_spacing(input_mesh))) {
    const auto [foot, primitive] = input.tree.closest_point_and_primitive(cg(x));
    input.points.push_back(x);
    input.normals.push_back(input.face_normals[static_cast<size_t>(primitive - input.triangles.begin())]);
  }

  ConnectivityReport r;
  Candidate current = make_candidate(fitted);
  const int triangle_count = static_cast<int>(fitted.triangles.size());
  const int per_triangle = 1 << (2 * options.levels);
  // Every data point's control triangle, from one projection onto the whole limit mesh.
  std::vector<std::vector<int>> data_of(triangle_count);
  {
    const TriangleMesh surface =
        evaluate_limit_mesh(subdivision_limit_mesh(control_mesh_topology(current.mesh), options.levels), current.mesh.positions);
    std::vector<K::Triangle_3> triangles;
    for (const auto& t : surface.triangles)
      triangles.emplace_back(cg(surface.positions[t[0]]), cg(surface.positions[t[1]]), cg(surface.positions[t[2]]));
    TriangleTree tree(triangles.begin(), triangles.end());
    tree.accelerate_distance_queries();
    for (size_t i = 0; i < input.points.size(); ++i) {
      const auto primitive = tree.closest_point_and_primitive(cg(input.points[i])).second;
      data_of[static_cast<size_t>(primitive - triangles.begin()) / per_triangle].push_back(static_cast<int>(i));
    }
  }
  const double edges = 1.5 * triangle_count;
  const double spring_weight =
      options.fairness * static_cast<double>(input.points.size() + static_cast<size_t>(triangle_count) * per_triangle) /
      (static_cast<double>(fitted.positions.size()) + 2 * edges);
  const LocalFit local(input, options, spring_weight);

  // The region a move touches: control triangles with a vertex within one ring of the free vertices
  // (their limit patches depend on the moved points and on the changed connectivity).
  auto region_of = [&](const Candidate& c, const std::set<int>& free) {
    std::set<int> region;
    for (const int v : grow(c, free, 1))
      for (const int t : c.vertex_triangles[v]) region.insert(t);
    return std::vector<int>(region.begin(), region.end());
  };
  {
    std::vector<int> all(triangle_count);
    for (int t = 0; t < triangle_count; ++t) all[t] = t;
    std::vector<int> data(input.points.size());
    for (size_t i = 0; i < data.size(); ++i) data[i] = static_cast<int>(i);
    r.energy_before = local.energy(current, all, data, {}, nullptr);
  }

  for (int sweep = 0; sweep < options.sweeps; ++sweep) {
    int kept_this_sweep = 0;
    // Candidate moves from the current mesh (re-listed each sweep; a move made stale by an earlier one
    // in the same sweep is checked again before it is tried).
    const ControlMeshEdges list_edges = control_mesh_edges(control_mesh_topology(current.mesh));
    ControlMeshEdges now = list_edges;  // the current mesh's edges, redone when a move is kept
    std::vector<std::pair<int, int>> candidates;  // (0 swap / 1 corner toggle / 2 crease toggle, edge or vertex)
    if (options.swaps)
      for (size_t e = 0; e < list_edges.ends.size(); ++e)
        if (!list_edges.sharp[e] && list_edges.face_count[e] == 2) candidates.push_back({0, static_cast<int>(e)});
    if (options.corner_toggles)
      for (int v = 0; v < static_cast<int>(current.mesh.positions.size()); ++v) candidates.push_back({1, v});
    if (options.crease_toggles)
      for (size_t e = 0; e < list_edges.ends.size(); ++e)
        if (list_edges.face_count[e] == 2) candidates.push_back({2, static_cast<int>(e)});

    for (const auto& [kind, id] : candidates) {
      Move move;
      move.mesh = current.mesh;
      if (kind == 0 || kind == 2) {
        // The edge by its ends in the list it was found in; find it again in the current mesh.
        const auto [a, b] = list_edges.ends[id];
        int e = -1;
        for (const int f : now.vertex_edges[a])
          if (other_end(now, f, a) == b) e = f;
        if (e < 0 || now.face_count[e] != 2) continue;
        if (kind == 2) {
          auto& creases = move.mesh.crease_edges;
          const std::array<int, 2> tag{a, b};
          const auto it = std::find(creases.begin(), creases.end(), tag);
          if (it == creases.end()) creases.push_back(tag);
          else creases.erase(it);
          move.changed = {a, b};
        } else {
          if (now.sharp[e]) continue;
          const int c = now.opposite[e][0], d = now.opposite[e][1];
          if (c == d || now.vertex_edges[a].size() <= 3 || now.vertex_edges[b].size() <= 3) continue;
          bool joined = false;
          for (const int f : now.vertex_edges[c]) joined |= other_end(now, f, c) == d;
          if (joined) continue;
          // The two triangles of edge a-b: t0 runs a -> b (opposite c), t1 runs b -> a (opposite d).
          int t0 = -1, t1 = -1;
          for (const int t : current.vertex_triangles[a]) {
            const auto& tri = current.mesh.triangles[t];
            for (int k = 0; k < 3; ++k) {
              if (tri[k] == a && tri[(k + 1) % 3] == b) t0 = t;
              if (tri[k] == b && tri[(k + 1) % 3] == a) t1 = t;
            }
          }
          if (t0 < 0 || t1 < 0) continue;
          const int c0 = [&] {
            for (const int v : current.mesh.triangles[t0])
              if (v != a && v != b) return v;
            return -1;
          }();
          const int d0 = [&] {
            for (const int v : current.mesh.triangles[t1])
              if (v != a && v != b) return v;
            return -1;
          }();
          move.mesh.triangles[t0] = {c0, a, d0};
          move.mesh.triangles[t1] = {d0, b, c0};
          const auto& p = current.mesh.positions;
          const Eigen::Vector3d old_normal = unit_normal(p[a], p[b], p[c0]) + unit_normal(p[b], p[a], p[d0]);
          if (unit_normal(p[c0], p[a], p[d0]).dot(old_normal) <= 0 || unit_normal(p[d0], p[b], p[c0]).dot(old_normal) <= 0)
            continue;
          move.changed = {a, b, c0, d0};
        }
      } else {
        if (now.vertex_kind[id] != ControlVertexKind::crease &&
            std::find(current.mesh.corner_vertices.begin(), current.mesh.corner_vertices.end(), id) ==
                current.mesh.corner_vertices.end())
          continue;  // a corner tag changes only a crease vertex (3+ sharp edges are corners anyway)
        auto& corners = move.mesh.corner_vertices;
        const auto it = std::find(corners.begin(), corners.end(), id);
        if (it == corners.end()) corners.push_back(id);
        else corners.erase(it);
        move.changed = {id};
      }

      Candidate after = make_candidate(std::move(move.mesh));
      const std::set<int> free_set = grow(after, move.changed, options.free_rings);
      std::vector<int> region = region_of(after, free_set);
      {
        const std::vector<int> before_region = region_of(current, free_set);
        std::set<int> both(region.begin(), region.end());
        both.insert(before_region.begin(), before_region.end());
        region.assign(both.begin(), both.end());
      }
      std::vector<int> data;
      for (const int t : region) data.insert(data.end(), data_of[t].begin(), data_of[t].end());
      if (data.empty()) continue;
      ++r.candidates;
      const double before = local.energy(current, region, data, {}, nullptr);
      std::vector<int> feet;
      double after_energy = INFINITY;
      try {
        after_energy = local.energy(after, region, data, std::vector<int>(free_set.begin(), free_set.end()), &feet);
      } catch (const std::invalid_argument&) {
        continue;  // the move made a mesh Loop's rules refuse
      }
      if (!(after_energy < (1 - 1e-4) * before)) continue;
      // Keep it: the region's data points go to the triangles they now project onto.
      for (const int t : region) data_of[t].clear();
      for (size_t i = 0; i < data.size(); ++i) data_of[feet[i]].push_back(data[i]);
      current = std::move(after);
      now = control_mesh_edges(control_mesh_topology(current.mesh));
      ++kept_this_sweep;
      (kind == 0 ? r.swaps : kind == 1 ? r.corner_toggles : r.crease_toggles)++;
    }
    if (kept_this_sweep == 0) break;
  }
  {
    std::vector<int> all(triangle_count);
    for (int t = 0; t < triangle_count; ++t) all[t] = t;
    std::vector<int> data;
    for (const auto& d : data_of) data.insert(data.end(), d.begin(), d.end());
    r.energy_after = local.energy(current, all, data, {}, nullptr);
  }
  if (report) *report = r;
  return current.mesh;
}

}  // namespace cadnurbs
