#include "analysis/mesh/weld_polygon_meshes.hpp"

#include "analysis/mesh/point_hash_grid.hpp"

namespace cadnurbs {

namespace {

// The index of the position `p` is welded to (the first within `tolerance`), adding it when it is new.
int welded_index(const Eigen::Vector3d& p, double tolerance, PointHashGrid& grid, std::vector<Eigen::Vector3d>& positions) {
  int found = -1;
  grid.find_near(p, [&](int k) {
    if ((positions[k] - p).norm() > tolerance) return false;
    found = k;
    return true;
  });
  if (found >= 0) return found;
  positions.push_back(p);
  grid.insert(p, static_cast<int>(positions.size()) - 1);
  return static_cast<int>(positions.size()) - 1;
}

}  // namespace

PolygonMesh weld_polygon_meshes(const std::vector<PolygonMesh>& meshes, double tolerance) {
  PolygonMesh out;
  PointHashGrid grid(tolerance > 0 ? tolerance : 1.0);
  for (const auto& mesh : meshes)
    for (const auto& polygon : mesh.polygons) {
      std::vector<int> corners;
      for (int k : polygon) {
        const int welded = welded_index(mesh.positions[k], tolerance, grid, out.positions);
        if (corners.empty() || corners.back() != welded) corners.push_back(welded);
      }
      while (corners.size() > 1 && corners.front() == corners.back()) corners.pop_back();
      if (corners.size() >= 3) out.polygons.push_back(std::move(corners));
    }
  return out;
}

}  // namespace cadnurbs
