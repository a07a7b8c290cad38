#include "analysis/normals/orient_faces.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>

#include "analysis/mesh/side_partners.hpp"
#include "analysis/mesh/vertex_buckets.hpp"
#include "core/worker_threads.hpp"

namespace cadnurbs {

namespace {

// Marks the triangles whose vertex set an earlier triangle already has. Triangles are bucketed by their
// lowest vertex and each small bucket sorted by the other two, so no hash of triples.
std::vector<char> duplicate_triangles(const TriangleMesh& mesh) {
  const auto& T = mesh.triangles;
  std::vector<char> duplicate(T.size(), 0);
  std::vector<std::vector<std::pair<std::uint64_t, int>>> keyed(worker_threads());  // (middle, highest), triangle
  auto lowest = [&](std::size_t t, int) {
    return BucketEntry{static_cast<std::size_t>(std::min({T[t][0], T[t][1], T[t][2]})), t};
  };
  visit_vertex_buckets(mesh.positions.size(), T.size(), 1, lowest, [&](int w, std::uint64_t* begin, std::uint64_t* end) {
    if (end - begin < 2) return;
    auto& bucket = keyed[w];
    bucket.clear();
    for (const std::uint64_t* i = begin; i < end; ++i) {
      auto c = T[*i];
      std::sort(c.begin(), c.end());
      bucket.emplace_back(std::uint64_t{static_cast<std::uint32_t>(c[1])} << 32 | static_cast<std::uint32_t>(c[2]),
                          static_cast<int>(*i));
    }
    std::sort(bucket.begin(), bucket.end());  // the earliest triangle of equal keys first
    for (std::size_t i = 1; i < bucket.size(); ++i)
      if (bucket[i].first == bucket[i - 1].first) duplicate[bucket[i].second] = 1;
  });
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
  // gets the opposite flip. The triangles are shared out to `workers` threads in ranges, each flooding the
  // parts of components within its range (parts numbered in order of their first triangles); the parts are
  // then joined across the sides between ranges by the same flood over parts. In an orientable component
  // every flip follows from the first triangle's whatever the path, so any number of ranges gives one
  // range's result. Not so in a non-orientable one: when an edge is left inconsistent, the mesh is flooded
  // again in one range.
  std::vector<int> component(nt);
  std::vector<char> flip(nt);
  auto flood = [&](int workers) {
    std::fill(component.begin(), component.end(), -1);
    std::fill(flip.begin(), flip.end(), 0);
    std::vector<int> first_part(workers + 1, 0);      // range w's parts: first_part[w] ..
    std::vector<std::vector<int>> crossing(workers);  // sides whose partner lies in a later range
    on_workers(workers, [&](int w) {
      const auto [first, end] = worker_range(nt, w, workers);
      int parts = 0;
      std::vector<int> stack;
      for (std::size_t t0 = first; t0 < end; ++t0) {
        if (component[t0] >= 0) continue;
        component[t0] = parts;
        stack.push_back(static_cast<int>(t0));
        while (!stack.empty()) {
          const int t = stack.back();
          stack.pop_back();
          for (int k = 0; k < 3; ++k) {
            const int s = 3 * t + k, p = partner[s];
            if (p < 0) continue;
            const auto u = static_cast<std::size_t>(p / 3);
            if (u < first || u >= end) {
              if (p > s) crossing[w].push_back(s);
            } else if (component[u] < 0) {
              component[u] = parts;
              flip[u] = static_cast<char>(flip[t] ^ same_direction(s, p));
              stack.push_back(p / 3);
            }
          }
        }
        ++parts;
      }
      first_part[w + 1] = parts;
    });
    for (int w = 0; w < workers; ++w) first_part[w + 1] += first_part[w];
    auto part_of = [&](std::size_t t) {
      int w = 0;
      while (t >= worker_range(nt, w, workers).end) ++w;
      return first_part[w] + component[t];
    };
    // The parts' graph: for each side between ranges, its two parts and whether their flips differ.
    const int part_count = first_part[workers];
    std::vector<int> link_start(part_count + 2, 0);
    std::vector<std::pair<int, char>> links;  // (neighbouring part, flip difference), grouped by part
    for (int pass = 0; pass < 2; ++pass) {
      if (pass == 1) {
        for (int g = 0; g <= part_count; ++g) link_start[g + 1] += link_start[g];
        links.resize(link_start[part_count + 1]);
      }
      for (const std::vector<int>& sides_between : crossing)
        for (const int s : sides_between) {
          const int p = partner[s], a = part_of(s / 3), b = part_of(p / 3);
          const char differ = static_cast<char>(flip[s / 3] ^ flip[p / 3] ^ same_direction(s, p));
          if (pass == 0) {
            ++link_start[a + 2];
            ++link_start[b + 2];
          } else {
            links[link_start[a + 1]++] = {b, differ};
            links[link_start[b + 1]++] = {a, differ};
          }
        }
    }
    std::vector<int> part_component(part_count, -1);
    std::vector<char> part_flip(part_count, 0);
    std::vector<int> stack;
    r.components = 0;
    for (int g0 = 0; g0 < part_count; ++g0) {
      if (part_component[g0] >= 0) continue;
      part_component[g0] = r.components;
      stack.push_back(g0);
      while (!stack.empty()) {
        const int g = stack.back();
        stack.pop_back();
        for (int i = link_start[g]; i < link_start[g + 1]; ++i) {
          const auto [h, differ] = links[i];
          if (part_component[h] >= 0) continue;
          part_component[h] = r.components;
          part_flip[h] = static_cast<char>(part_flip[g] ^ differ);
          stack.push_back(h);
        }
      }
      ++r.components;
    }
    on_workers(workers, [&](int w) {
      const auto [first, end] = worker_range(nt, w, workers);
      for (std::size_t t = first; t < end; ++t) {
        const int g = first_part[w] + component[t];
        component[t] = part_component[g];
        flip[t] ^= part_flip[g];
      }
    });
  };
  flood(worker_threads());

  struct Component {
    bool closed = true, orientable = true;
    int origin = -1;    // a vertex of it, the apex of the volume's tetrahedra (keeps the sum's terms small)
    double volume = 0;  // six times the signed volume
  };
  std::vector<Component> parts;
  auto mark_inconsistent_edges = [&] {
    parts.assign(r.components, Component{});
    const int workers = worker_threads();
    std::vector<std::vector<int>> inconsistent(workers);  // each worker's, by the lower side
    on_workers(workers, [&](int w) {
      const auto [first, end] = worker_range(3 * nt, w, workers);
      for (std::size_t s = first; s < end; ++s) {
        const int p = partner[s];
        if (p < static_cast<int>(s)) continue;  // each two-face edge once
        if (same_direction(static_cast<int>(s), p) == (flip[s / 3] == flip[p / 3]))
          inconsistent[w].push_back(static_cast<int>(s));
      }
    });
    r.inconsistent_edges = 0;
    for (const std::vector<int>& sides_found : inconsistent)
      for (const int s : sides_found) {
        ++r.inconsistent_edges;
        parts[component[s / 3]].orientable = false;
      }
  };
  mark_inconsistent_edges();
  if (r.inconsistent_edges > 0 && worker_threads() > 1) {
    flood(1);
    mark_inconsistent_edges();
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
    const int workers = worker_threads();
    on_workers(workers, [&](int w) {
      const auto [first, end] = worker_range(nt, w, workers);
      for (std::size_t t = first; t < end; ++t) {
        if (flip[t]) std::swap(partner[3 * t], partner[3 * t + 2]);
        for (int k = 0; k < 3; ++k)
          if (partner[3 * t + k] >= 0) partner[3 * t + k] = moved(partner[3 * t + k]);
      }
    });
    *partners_of_output = std::move(sides);
  }
  return mesh;
}

}  // namespace cadnurbs
