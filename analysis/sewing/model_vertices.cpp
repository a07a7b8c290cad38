#include "analysis/sewing/model_vertices.hpp"

#include <algorithm>

#include "analysis/mesh/point_hash_grid.hpp"
#include "core/union_find.hpp"

namespace cadnurbs::sewing {

namespace {

// Cluster id per point: points closer than `tolerance` share one (transitively); ids 0, 1, ... in
// order of first appearance.
std::vector<int> cluster_points(const std::vector<Eigen::Vector3d>& points, double tolerance) {
  PointHashGrid grid(tolerance);
  UnionFind classes(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    grid.find_near(points[i], [&](int j) {
      if ((points[j] - points[i]).norm() <= tolerance) classes.unite(static_cast<int>(i), j);
      return false;  // every neighbour, not only the first
    });
    grid.insert(points[i], static_cast<int>(i));
  }
  std::vector<int> id(points.size(), -1), id_of_root(points.size(), -1);
  int next = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    int& root_id = id_of_root[classes.find(static_cast<int>(i))];
    if (root_id < 0) root_id = next++;
    id[i] = root_id;
  }
  return id;
}

}  // namespace

std::vector<Eigen::Vector3d> find_model_vertices(std::vector<Piece>& pieces, double tolerance) {
  std::vector<Eigen::Vector3d> ends;
  for (const auto& p : pieces) {
    ends.push_back(p.points.front());
    ends.push_back(p.points.back());
  }
  const std::vector<int> id = cluster_points(ends, tolerance);
  std::vector<Eigen::Vector3d> position(ends.empty() ? 0 : *std::max_element(id.begin(), id.end()) + 1);
  for (size_t i = ends.size(); i-- > 0;) position[id[i]] = ends[i];  // the first point of each cluster
  for (size_t i = 0; i < pieces.size(); ++i) pieces[i].start = {id[2 * i]}, pieces[i].end = {id[2 * i + 1]};
  return position;
}

}  // namespace cadnurbs::sewing
