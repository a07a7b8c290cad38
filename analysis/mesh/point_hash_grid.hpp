#pragma once
// Points hashed into cubic cells of a given size, so that every point within that distance of a query is
// found by looking in the 27 cells around it (none missed at a cell border). The one neighbour search of
// weld_polygon_meshes (greedy welding), sew_faces (vertex clusters) and nurss_from_nurbs.
#include <Eigen/Core>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace cadnurbs {

class PointHashGrid {
 public:
  // cell > 0: the largest distance the searches are for.
  explicit PointHashGrid(double cell) : cell_(cell) {}

  void insert(const Eigen::Vector3d& p, int index) { cells_[key(cell_of(p))].push_back(index); }

  // Calls visit(index) for the points inserted in the 27 cells around p (a superset of those within
  // `cell` of p), until visit returns true; returns whether one did.
  template <class Visit>
  bool find_near(const Eigen::Vector3d& p, Visit&& visit) const {
    const Cell c = cell_of(p);
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          const auto it = cells_.find(key({c.x + dx, c.y + dy, c.z + dz}));
          if (it == cells_.end()) continue;
          for (int index : it->second)
            if (visit(index)) return true;
        }
    return false;
  }

 private:
  struct Cell {
    long long x, y, z;
  };
  Cell cell_of(const Eigen::Vector3d& p) const {
    return {static_cast<long long>(std::floor(p.x() / cell_)), static_cast<long long>(std::floor(p.y() / cell_)),
            static_cast<long long>(std::floor(p.z() / cell_))};
  }
  static unsigned long long key(const Cell& c) {
    return static_cast<unsigned long long>(c.x) * 73856093ull ^ static_cast<unsigned long long>(c.y) * 19349663ull ^
           static_cast<unsigned long long>(c.z) * 83492791ull;
  }

  double cell_;
  std::unordered_map<unsigned long long, std::vector<int>> cells_;  // hashed cells may share a bucket list
};

}  // namespace cadnurbs
