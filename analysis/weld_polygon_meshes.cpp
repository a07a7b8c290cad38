#include "analysis/weld_polygon_meshes.hpp"

#include <cmath>
#include <unordered_map>

namespace cadnurbs {

namespace {

struct CellHash {
  size_t operator()(const Eigen::Vector3i& c) const {
    return (static_cast<size_t>(c.x()) * 73856093u) ^ (static_cast<size_t>(c.y()) * 19349663u) ^
           (static_cast<size_t>(c.z()) * 83492791u);
  }
};
struct CellEqual {
  bool operator()(const Eigen::Vector3i& a, const Eigen::Vector3i& b) const { return a == b; }
};

class WeldGrid {
 public:
  explicit WeldGrid(double tolerance) : tolerance_(tolerance), cell_(tolerance > 0 ? tolerance : 1.0) {}

  // The index of the position `p` is welded to, adding it when it is new.
  int index_of(const Eigen::Vector3d& p, std::vector<Eigen::Vector3d>& positions) {
    const Eigen::Vector3i c = cell(p);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          auto it = cells_.find(c + Eigen::Vector3i(dx, dy, dz));
          if (it == cells_.end()) continue;
          for (int k : it->second)
            if ((positions[k] - p).norm() <= tolerance_) return k;
        }
    const int k = static_cast<int>(positions.size());
    positions.push_back(p);
    cells_[c].push_back(k);
    return k;
  }

 private:
  Eigen::Vector3i cell(const Eigen::Vector3d& p) const {
    return Eigen::Vector3i(static_cast<int>(std::floor(p.x() / cell_)), static_cast<int>(std::floor(p.y() / cell_)),
                           static_cast<int>(std::floor(p.z() / cell_)));
  }

  double tolerance_, cell_;
  std::unordered_map<Eigen::Vector3i, std::vector<int>, CellHash, CellEqual> cells_;
};

}  // namespace

PolygonMesh weld_polygon_meshes(const std::vector<PolygonMesh>& meshes, double tolerance) {
  PolygonMesh out;
  WeldGrid grid(tolerance);
  for (const auto& mesh : meshes)
    for (const auto& polygon : mesh.polygons) {
      std::vector<int> corners;
      for (int k : polygon) {
        const int welded = grid.index_of(mesh.positions[k], out.positions);
        if (corners.empty() || corners.back() != welded) corners.push_back(welded);
      }
      while (corners.size() > 1 && corners.front() == corners.back()) corners.pop_back();
      if (corners.size() >= 3) out.polygons.push_back(std::move(corners));
    }
  return out;
}

}  // namespace cadnurbs
