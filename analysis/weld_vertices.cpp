#include "analysis/weld_vertices.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "analysis/point_hash_grid.hpp"
#include "core/union_find.hpp"

namespace cadnurbs {

namespace {

Eigen::AlignedBox3d positions_box(const TriangleMesh& mesh) {
  Eigen::AlignedBox3d box;
  for (const auto& p : mesh.positions) box.extend(p);
  return box;
}

}  // namespace

double default_weld_tolerance(const TriangleMesh& mesh) {
  if (mesh.positions.empty()) return 0;
  return 1e-6 * positions_box(mesh).diagonal().norm();
}

TriangleMesh weld_vertices(const TriangleMesh& mesh, double tolerance, WeldReport* report) {
  if (!(tolerance >= 0) || !std::isfinite(tolerance))
    throw std::invalid_argument("weld_vertices: tolerance must be finite and >= 0, got " + std::to_string(tolerance));
  validate(mesh, "weld_vertices input");
  const size_t n = mesh.positions.size();
  const Eigen::AlignedBox3d box = positions_box(mesh);
  const Eigen::Vector3d origin = n ? box.min() : Eigen::Vector3d::Zero();
  // The cell must be at least the tolerance in the rounded arithmetic too: a pair within the tolerance
  // may not end up two cells apart because (p - origin) / cell rounded. The slack covers the rounding
  // of the subtraction (an ulp of the coordinates) and of the division (an ulp of the extent).
  const double extent = n ? (box.max() - box.min()).cwiseAbs().maxCoeff() : 0.0;
  const double magnitude = n ? std::max(box.min().cwiseAbs().maxCoeff(), box.max().cwiseAbs().maxCoeff()) : 0.0;
  double cell = tolerance + 8 * std::numeric_limits<double>::epsilon() * (magnitude + extent);
  // Cells are counted in 64-bit integers: never more than 2^40 along an axis (a larger cell only adds
  // candidates, never loses one).
  cell = std::max(cell, extent / 1e12);
  if (!(cell > 0)) cell = 1;  // all points equal (or none): any cell holds them
  const double tolerance2 = tolerance * tolerance;

  UnionFind classes(n);
  PointHashGrid grid(cell);
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d p = mesh.positions[i] - origin;
    grid.find_near(p, [&](int j) {
      if ((mesh.positions[i] - mesh.positions[j]).squaredNorm() <= tolerance2) classes.unite(static_cast<int>(i), j);
      return false;  // every neighbour: the pair may join two classes found earlier
    });
    grid.insert(p, static_cast<int>(i));
  }

  WeldReport r;
  r.input_vertices = static_cast<int>(n);
  std::vector<int> root(n);
  for (size_t i = 0; i < n; ++i) {
    root[i] = classes.find(static_cast<int>(i));
    if (root[i] == static_cast<int>(i)) ++r.vertex_classes;
    r.largest_merge_distance = std::max(r.largest_merge_distance, (mesh.positions[i] - mesh.positions[root[i]]).norm());
  }

  TriangleMesh out;
  std::vector<int> index(n, -1);  // class root -> output vertex
  const bool normals = mesh.corner_normals.size() == 3 * mesh.triangles.size() && !mesh.triangles.empty();
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const std::array<int, 3> c{root[tri[0]], root[tri[1]], root[tri[2]]};
    if (c[0] == c[1] || c[1] == c[2] || c[2] == c[0]) {
      ++r.collapsed_triangles;
      continue;
    }
    const auto& a = mesh.positions[c[0]];
    if ((mesh.positions[c[1]] - a).cross(mesh.positions[c[2]] - a).squaredNorm() == 0) {
      ++r.zero_area_triangles;
      continue;
    }
    std::array<int, 3> kept{};
    for (int k = 0; k < 3; ++k) {
      if (index[c[k]] < 0) {
        index[c[k]] = static_cast<int>(out.positions.size());
        out.positions.push_back(mesh.positions[c[k]]);
      }
      kept[k] = index[c[k]];
    }
    out.triangles.push_back(kept);
    if (normals)
      for (int k = 0; k < 3; ++k) out.corner_normals.push_back(mesh.corner_normals[3 * t + k]);
  }
  r.output_vertices = static_cast<int>(out.positions.size());
  if (report) *report = r;
  return out;
}

}  // namespace cadnurbs
