#include "analysis/orient_faces.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>

#include "analysis/edge_sides.hpp"

namespace cadnurbs {

namespace {

// Marks the triangles whose vertex set an earlier triangle already has. Triangles are bucketed by their
// lowest vertex (counting sort) and each small bucket sorted by the other two, so no hash of triples.
std::vector<char> duplicate_triangles(const TriangleMesh& mesh) {
  const auto& T = mesh.triangles;
  std::vector<int> start(mesh.positions.size() + 1, 0);
  for (const auto& t : T) ++start[std::min({t[0], t[1], t[2]}) + 1];
  for (std::size_t v = 1; v < start.size(); ++v) start[v] += start[v - 1];
  std::vector<int> order(T.size());
  {
    std::vector<int> next(start.begin(), start.end() - 1);
    for (std::size_t t = 0; t < T.size(); ++t) order[next[std::min({T[t][0], T[t][1], T[t][2]})]++] = static_cast<int>(t);
  }
  std::vector<char> duplicate(T.size(), 0);
  std::vector<std::pair<std::uint64_t, int>> keyed;  // (middle, highest vertex), triangle
  for (std::size_t v = 0; v + 1 < start.size(); ++v) {
    if (start[v + 1] - start[v] < 2) continue;
    keyed.clear();
    for (int i = start[v]; i < start[v + 1]; ++i) {
      auto c = T[order[i]];
      std::sort(c.begin(), c.end());
      keyed.emplace_back(std::uint64_t{static_cast<std::uint32_t>(c[1])} << 32 | static_cast<std::uint32_t>(c[2]), order[i]);
    }
    std::sort(keyed.begin(), keyed.end());  // the earliest triangle of equal keys first
    for (std::size_t i = 1; i < keyed.size(); ++i)
      if (keyed[i].first == keyed[i - 1].first) duplicate[keyed[i].second] = 1;
  }
  return duplicate;
}

}  // namespace

TriangleMesh orient_faces(TriangleMesh mesh, OrientReport* report, std::vector<int>* component_of_triangle,
                          SidePartners* partners_of_output) {
  validate(mesh, "orient_faces input");
  OrientReport r;
  const bool normals = !mesh.corner_normals.empty();
  {
    const std::vector<char> duplicate = duplicate_triangles(mesh);
    std::size_t kept = 0;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      if (duplicate[t]) continue;
      mesh.triangles[kept] = mesh.triangles[t];
      if (normals)
        for (int k = 0; k < 3; ++k) mesh.corner_normals[3 * kept + k] = mesh.corner_normals[3 * t + k];
      ++kept;
    }
    r.duplicate_triangles = static_cast<int>(mesh.triangles.size() - kept);
    mesh.triangles.resize(kept);
    if (normals) mesh.corner_normals.resize(3 * kept);
  }
  const auto& T = mesh.triangles;
  const std::size_t nt = T.size();

  // partner[s]: the other side of s's edge when that edge has exactly two faces, else -1.
  SidePartners sides = side_partners(mesh);
  r.boundary_edges = sides.boundary_edges;
  r.non_manifold_edges = sides.non_manifold_edges;
  std::vector<int>& partner = sides.partner;
  // Two sides of one edge run the same way when they start at the same vertex.
  auto same_direction = [&](int s, int p) { return side_from(mesh, s) == side_from(mesh, p); };

  // Flood each component from its first triangle; a neighbour reached across a side running its way
  // gets the opposite flip.
  std::vector<int> component(nt, -1);
  std::vector<char> flip(nt, 0);
  std::vector<int> stack;
  for (std::size_t t0 = 0; t0 < nt; ++t0) {
    if (component[t0] >= 0) continue;
    component[t0] = r.components;
    stack.push_back(static_cast<int>(t0));
    while (!stack.empty()) {
      const int t = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k) {
        const int s = 3 * t + k, p = partner[s];
        if (p < 0 || component[p / 3] >= 0) continue;
        component[p / 3] = r.components;
        flip[p / 3] = static_cast<char>(flip[t] ^ same_direction(s, p));
        stack.push_back(p / 3);
      }
    }
    ++r.components;
  }

  struct Component {
    bool closed = true, orientable = true;
    int origin = -1;    // a vertex of it, the apex of the volume's tetrahedra (keeps the sum's terms small)
    double volume = 0;  // six times the signed volume
  };
  std::vector<Component> parts(r.components);
  for (std::size_t s = 0; s < 3 * nt; ++s) {
    const int p = partner[s];
    if (p < static_cast<int>(s)) continue;  // each two-face edge once
    const std::size_t t = s / 3, u = p / 3;
    if (same_direction(static_cast<int>(s), p) == (flip[t] == flip[u])) {
      ++r.inconsistent_edges;
      parts[component[t]].orientable = false;
    }
  }
  for (std::size_t t = 0; t < nt; ++t) {
    Component& part = parts[component[t]];
    if (partner[3 * t] < 0 || partner[3 * t + 1] < 0 || partner[3 * t + 2] < 0)
      part.closed = false;  // on a boundary or non-manifold edge
    if (part.origin < 0) part.origin = T[t][0];
    const Eigen::Vector3d& o = mesh.positions[part.origin];
    const Eigen::Vector3d a = mesh.positions[T[t][0]] - o, b = mesh.positions[T[t][1]] - o,
                          c = mesh.positions[T[t][2]] - o;
    part.volume += (flip[t] ? -1.0 : 1.0) * a.dot(b.cross(c));
  }
  for (const Component& part : parts) {
    r.closed_components += part.closed;
    r.non_orientable_components += !part.orientable;
  }

  for (std::size_t t = 0; t < nt; ++t) {
    const Component& part = parts[component[t]];
    if (part.closed && part.orientable && part.volume < 0) flip[t] ^= 1;
    if (!flip[t]) continue;
    ++r.flipped_triangles;
    std::swap(mesh.triangles[t][1], mesh.triangles[t][2]);
    if (normals) std::swap(mesh.corner_normals[3 * t + 1], mesh.corner_normals[3 * t + 2]);
  }
  if (report) *report = r;
  if (component_of_triangle) *component_of_triangle = std::move(component);
  if (partners_of_output) {
    // A flipped triangle's sides 0 and 2 trade edges (corners 0, 2, 1 run 0 -> 2, 2 -> 1, 1 -> 0), side 1
    // keeps its own: the partners follow.
    auto moved = [&](int s) { return flip[s / 3] && s % 3 != 1 ? s - s % 3 + 2 - s % 3 : s; };
    for (std::size_t t = 0; t < nt; ++t)
      if (flip[t]) std::swap(partner[3 * t], partner[3 * t + 2]);
    for (int& p : partner)
      if (p >= 0) p = moved(p);
    *partners_of_output = std::move(sides);
  }
  return mesh;
}

}  // namespace cadnurbs
