#include "analysis/subdivision_fit/limit_patches.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace cadnurbs {

LimitPatches limit_patches(const ControlMeshTopology& control, const std::vector<std::vector<int>>& vertex_triangles,
                                    const std::vector<int>& region, int levels) {
  if (levels < 0 || levels > 8) throw std::invalid_argument("limit_patches: levels must be 0 to 8");
  const int triangle_count = static_cast<int>(control.triangles.size());
  std::vector<int> sorted_region = region;
  std::sort(sorted_region.begin(), sorted_region.end());
  for (size_t i = 0; i < sorted_region.size(); ++i) {
    const int t = sorted_region[i];
    if (t < 0 || t >= triangle_count)
      throw std::invalid_argument("limit_patches: triangle " + std::to_string(t) + " is out of range");
    if (i > 0 && sorted_region[i - 1] == t)
      throw std::invalid_argument("limit_patches: triangle " + std::to_string(t) + " is given twice");
  }

  // The sub-mesh: the region first (so its patches come first), then its 1-ring's other triangles.
  std::vector<int> ring;
  for (const int t : region)
    for (const int v : control.triangles[t]) {
      if (v < 0 || v >= static_cast<int>(vertex_triangles.size()))
        throw std::invalid_argument("limit_patches: triangle " + std::to_string(t) + " has a vertex out of range");
      for (const int u : vertex_triangles[v])
        if (!std::binary_search(sorted_region.begin(), sorted_region.end(), u)) ring.push_back(u);
    }
  std::sort(ring.begin(), ring.end());
  ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
  std::vector<int> sub_triangles = region;
  sub_triangles.insert(sub_triangles.end(), ring.begin(), ring.end());

  std::vector<int> global_of;  // the sub-mesh's vertices, sorted: local index = position
  for (const int t : sub_triangles) global_of.insert(global_of.end(), control.triangles[t].begin(), control.triangles[t].end());
  std::sort(global_of.begin(), global_of.end());
  global_of.erase(std::unique(global_of.begin(), global_of.end()), global_of.end());
  auto local = [&](int v) { return static_cast<int>(std::lower_bound(global_of.begin(), global_of.end(), v) - global_of.begin()); };
  auto is_local = [&](int v) { return std::binary_search(global_of.begin(), global_of.end(), v); };

  ControlMeshTopology sub;
  sub.vertex_count = static_cast<int>(global_of.size());
  std::vector<std::array<int, 2>> sub_edges;  // global ends, {a < b}
  for (const int t : sub_triangles) {
    const auto& tri = control.triangles[t];
    sub.triangles.push_back({local(tri[0]), local(tri[1]), local(tri[2])});
    for (int k = 0; k < 3; ++k) sub_edges.push_back({std::min(tri[k], tri[(k + 1) % 3]), std::max(tri[k], tri[(k + 1) % 3])});
  }
  std::sort(sub_edges.begin(), sub_edges.end());
  // Tags on the sub-mesh's edges and vertices only (a tag between two ring vertices may join them
  // through a triangle outside it).
  for (const auto& c : control.crease_edges) {
    const std::array<int, 2> key{std::min(c[0], c[1]), std::max(c[0], c[1])};
    if (std::binary_search(sub_edges.begin(), sub_edges.end(), key)) sub.crease_edges.push_back({local(key[0]), local(key[1])});
  }
  for (const int v : control.corner_vertices)
    if (is_local(v)) sub.corner_vertices.push_back(local(v));

  const SubdivisionLimitMesh limit = subdivision_limit_mesh(sub, levels);
  const size_t patch_triangles = region.size() << (2 * levels);
  LimitPatches out;
  out.triangles.assign(limit.level.triangles.begin(), limit.level.triangles.begin() + static_cast<long>(patch_triangles));
  std::vector<int> row_of(static_cast<size_t>(limit.limit_from_control.rows()), -1);
  std::vector<int> rows;  // the sub-mesh map's rows kept, in the new order
  for (auto& tri : out.triangles)
    for (int& v : tri) {
      if (row_of[v] < 0) {
        row_of[v] = static_cast<int>(rows.size());
        rows.push_back(v);
      }
      v = row_of[v];
    }
  std::vector<Eigen::Triplet<double>> weights;
  for (size_t r = 0; r < rows.size(); ++r)
    for (LimitStencils::InnerIterator it(limit.limit_from_control, rows[r]); it; ++it)
      weights.emplace_back(static_cast<int>(r), global_of[it.col()], it.value());
  out.limit_from_control.resize(static_cast<long>(rows.size()), control.vertex_count);
  out.limit_from_control.setFromTriplets(weights.begin(), weights.end());
  return out;
}

}  // namespace cadnurbs
