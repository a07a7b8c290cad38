#include "analysis/nurss/nurss_from_nurbs.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "analysis/mesh/point_hash_grid.hpp"
#include "core/geometry_error.hpp"

namespace cadnurbs {

namespace {

// d_i = t_{i+2} - t_{i+1} for every control point of one direction.
std::vector<double> point_intervals(const std::vector<double>& knots, int count) {
  std::vector<double> d(count);
  for (int i = 0; i < count; ++i) d[i] = knots[i + 2] - knots[i + 1];
  return d;
}

}  // namespace

NurssMesh nurss_from_nurbs(const std::vector<NurbsSurface>& surfaces, double weld_tolerance) {
  NurssMesh mesh;
  PointHashGrid grid(weld_tolerance > 0 ? weld_tolerance : 1.0);  // used only when welding
  // Vertex of every control point, per surface.
  std::vector<std::vector<NurssVertexId>> vertex_of(surfaces.size());
  for (size_t s = 0; s < surfaces.size(); ++s) {
    const NurbsSurface& surface = surfaces[s];
    const std::string entity = "surface " + std::to_string(s);
    validate(surface, entity);
    if (surface.u_order != 3 || surface.v_order != 3)
      throw GeometryError(entity, "is of order " + std::to_string(surface.u_order) + " x " +
                                      std::to_string(surface.v_order) + "; a quadratic NURSS needs order 3 x 3");
    for (int k = 0; k < surface.u_count * surface.v_count; ++k) {
      const Eigen::Vector3d& p = surface.points[k];
      const double w = surface.weights.empty() ? 1.0 : surface.weights[k];
      int found = -1;
      if (weld_tolerance > 0)
        grid.find_near(p, [&](int v) {
          const NurssVertexId id(v);
          if ((mesh.position(id) - p).norm() > weld_tolerance) return false;
          if (std::abs(mesh.weight(id) - w) > 1e-9 * std::max(w, mesh.weight(id))) return false;
          found = v;
          return true;
        });
      if (found < 0) {
        found = mesh.add_vertex(p, w).value;
        if (weld_tolerance > 0) grid.insert(p, found);
      }
      vertex_of[s].emplace_back(found);
    }
  }
  // Faces, then intervals (an edge exists once both its faces or its one face are in).
  for (size_t s = 0; s < surfaces.size(); ++s) {
    const NurbsSurface& surface = surfaces[s];
    const auto& v = vertex_of[s];
    for (int j = 0; j + 1 < surface.v_count; ++j)
      for (int i = 0; i + 1 < surface.u_count; ++i) {
        const std::vector<NurssVertexId> quad = {v[surface.index(i, j)], v[surface.index(i + 1, j)],
                                                 v[surface.index(i + 1, j + 1)], v[surface.index(i, j + 1)]};
        for (int k = 0; k < 4; ++k)
          for (int l = 0; l < k; ++l)
            if (quad[k] == quad[l])
              throw GeometryError("surface " + std::to_string(s) + ", quad (" + std::to_string(i) + ", " +
                                      std::to_string(j) + ")",
                                  "two corners weld into one vertex (a pole); NURSS faces need distinct corners");
        mesh.add_face(quad);
      }
  }
  // Intervals set by some net, to find nets that disagree.
  std::map<std::pair<int, int>, double> set;
  auto give = [&](NurssVertexId at, NurssVertexId toward, double d, const std::string& entity) {
    const auto [it, fresh] = set.emplace(std::make_pair(at.value, toward.value), d);
    if (!fresh && std::abs(it->second - d) > 1e-9 * std::max(std::abs(d), std::abs(it->second)))
      throw GeometryError(entity, "vertex " + std::to_string(at.value) + " gets knot interval " +
                                      std::to_string(d) + " from one net and " + std::to_string(it->second) +
                                      " from another on the same edge");
    mesh.set_interval(at, toward, d);
  };
  for (size_t s = 0; s < surfaces.size(); ++s) {
    const NurbsSurface& surface = surfaces[s];
    const std::string entity = "surface " + std::to_string(s);
    const auto& v = vertex_of[s];
    const std::vector<double> du = point_intervals(surface.u_knots, surface.u_count);
    const std::vector<double> dv = point_intervals(surface.v_knots, surface.v_count);
    for (int j = 0; j < surface.v_count; ++j)
      for (int i = 0; i < surface.u_count; ++i) {
        const NurssVertexId p = v[surface.index(i, j)];
        if (i > 0) give(p, v[surface.index(i - 1, j)], du[i], entity);
        if (i + 1 < surface.u_count) give(p, v[surface.index(i + 1, j)], du[i], entity);
        if (j > 0) give(p, v[surface.index(i, j - 1)], dv[j], entity);
        if (j + 1 < surface.v_count) give(p, v[surface.index(i, j + 1)], dv[j], entity);
      }
  }
  return mesh;
}

std::vector<NurssFaceId> fill_boundary_loops(NurssMesh& mesh, int label) {
  // Boundary sides a→b (b→a in no face), by start vertex.
  std::map<int, NurssVertexId> next;
  std::vector<int> starts;
  for (int f = 0; f < mesh.face_count(); ++f) {
    const auto& c = mesh.corners(NurssFaceId(f));
    const int n = static_cast<int>(c.size());
    for (int k = 0; k < n; ++k) {
      const NurssVertexId a = c[k], b = c[(k + 1) % n];
      if (mesh.face_with_side(b, a)) continue;
      if (!next.emplace(a.value, b).second)
        throw GeometryError("NURSS vertex " + std::to_string(a.value), "lies on two boundary loops");
      starts.push_back(a.value);
    }
  }
  std::vector<std::vector<NurssVertexId>> loops;
  std::map<int, bool> used;
  for (int start : starts) {
    if (used[start]) continue;
    std::vector<NurssVertexId> loop;
    int v = start;
    while (!used[v]) {
      used[v] = true;
      loop.emplace_back(v);
      const auto it = next.find(v);
      if (it == next.end()) throw GeometryError("NURSS vertex " + std::to_string(v), "ends an open boundary chain");
      v = it->second.value;
    }
    if (v != start) throw GeometryError("NURSS vertex " + std::to_string(v), "lies on two boundary loops");
    if (loop.size() < 3)
      throw GeometryError("NURSS boundary loop at vertex " + std::to_string(start),
                          "has " + std::to_string(loop.size()) + " edges; a face needs 3 or more");
    std::reverse(loop.begin(), loop.end());
    loops.push_back(std::move(loop));
  }
  std::vector<NurssFaceId> added;
  for (const auto& loop : loops) added.push_back(mesh.add_face(loop, label));
  return added;
}

}  // namespace cadnurbs
