#include "analysis/weld_vertices.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>

#include "core/equal_points.hpp"
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
  const std::size_t n = mesh.positions.size();
  // Bitwise-equal vertices first (an STL file repeats each about six times), numbered in order of first
  // occurrence, so that the distance search sees each point once.
  EqualPoints equal;
  std::vector<int> point_of_vertex(n);
  for (std::size_t v = 0; v < n; ++v) point_of_vertex[v] = equal.add(mesh.positions[v]);
  const std::size_t m = equal.points().size();
  auto point = [&](int q) -> const Eigen::Vector3d& { return equal.points()[q]; };

  const Eigen::AlignedBox3d box = positions_box(mesh);
  const Eigen::Vector3d origin = n ? box.min() : Eigen::Vector3d::Zero();
  // The cell must be at least the tolerance in the rounded arithmetic too: a pair within the tolerance
  // may not end up two cells apart because (p - origin) / cell rounded. The slack covers the rounding
  // of the subtraction (an ulp of the coordinates) and of the division (an ulp of the extent).
  const double extent = n ? (box.max() - box.min()).cwiseAbs().maxCoeff() : 0.0;
  const double magnitude = n ? std::max(box.min().cwiseAbs().maxCoeff(), box.max().cwiseAbs().maxCoeff()) : 0.0;
  double cell = tolerance + 8 * std::numeric_limits<double>::epsilon() * (magnitude + extent);
  // Cells are counted in 32-bit integers: never more than 2^30 along an axis (a larger cell only adds
  // candidates, never loses one).
  cell = std::max(cell, extent / 0x1p30);
  if (!(cell > 0)) cell = 1;  // all points equal (or none): any cell holds them
  const double tolerance2 = tolerance * tolerance;

  // The points sorted by cell (x, then y, then z). Every pair within the tolerance lies in one cell or in
  // two neighbouring ones; of a cell's 26 neighbours the 13 that sort after it form five runs in this
  // order (same x and y: the next z; same x, next y; next x with three y), each a contiguous stretch
  // z - 1 .. z + 1, and as the cells advance each run's start only moves forward: one sweep, O(m).
  struct Entry {
    std::int32_t x, y, z;
    int point;
  };
  std::vector<Entry> entries(m);
  for (std::size_t q = 0; q < m; ++q) {
    const Eigen::Vector3d c = ((point(static_cast<int>(q)) - origin) / cell).array().floor();
    entries[q] = {static_cast<std::int32_t>(c.x()), static_cast<std::int32_t>(c.y()), static_cast<std::int32_t>(c.z()),
                  static_cast<int>(q)};
  }
  auto cell_less = [](const Entry& a, const Entry& b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); };
  std::sort(entries.begin(), entries.end(),
            [](const Entry& a, const Entry& b) { return std::tie(a.x, a.y, a.z, a.point) < std::tie(b.x, b.y, b.z, b.point); });
  UnionFind classes(m);
  auto compare = [&](const Entry& a, const Entry& b) {
    if ((point(a.point) - point(b.point)).squaredNorm() <= tolerance2) classes.unite(a.point, b.point);
  };
  constexpr std::array<std::array<int, 2>, 5> runs = {{{0, 0}, {0, 1}, {1, -1}, {1, 0}, {1, 1}}};
  std::array<std::size_t, 5> run_start{};
  for (std::size_t begin = 0, end = 0; begin < m; begin = end) {
    while (end < m && !cell_less(entries[begin], entries[end])) ++end;
    for (std::size_t i = begin; i < end; ++i)
      for (std::size_t j = i + 1; j < end; ++j) compare(entries[i], entries[j]);
    const Entry& here = entries[begin];
    for (std::size_t r = 0; r < runs.size(); ++r) {
      const Entry low{here.x + runs[r][0], here.y + runs[r][1], r == 0 ? here.z + 1 : here.z - 1, 0};
      const Entry high{low.x, low.y, here.z + 1, 0};
      std::size_t& start = run_start[r];
      while (start < m && cell_less(entries[start], low)) ++start;
      for (std::size_t q = start; q < m && !cell_less(high, entries[q]); ++q)
        for (std::size_t i = begin; i < end; ++i) compare(entries[i], entries[q]);
    }
  }
  entries = {};

  WeldReport r;
  r.input_vertices = static_cast<int>(n);
  std::vector<int> root(m);
  for (std::size_t q = 0; q < m; ++q) {
    root[q] = classes.find(static_cast<int>(q));
    if (root[q] == static_cast<int>(q)) ++r.vertex_classes;
    r.largest_merge_distance = std::max(r.largest_merge_distance, (point(static_cast<int>(q)) - point(root[q])).norm());
  }

  // A class's root is its smallest point, that of the class's first vertex in input order.
  TriangleMesh out;
  out.positions.reserve(r.vertex_classes);
  std::vector<int> index(m, -1);  // class root -> output vertex
  const bool normals = mesh.corner_normals.size() == 3 * mesh.triangles.size() && !mesh.triangles.empty();
  out.triangles.reserve(mesh.triangles.size());
  if (normals) out.corner_normals.reserve(mesh.corner_normals.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const std::array<int, 3> c{root[point_of_vertex[tri[0]]], root[point_of_vertex[tri[1]]], root[point_of_vertex[tri[2]]]};
    if (c[0] == c[1] || c[1] == c[2] || c[2] == c[0]) {
      ++r.collapsed_triangles;
      continue;
    }
    const auto& a = point(c[0]);
    if ((point(c[1]) - a).cross(point(c[2]) - a).squaredNorm() == 0) {
      ++r.zero_area_triangles;
      continue;
    }
    std::array<int, 3> kept{};
    for (int k = 0; k < 3; ++k) {
      if (index[c[k]] < 0) {
        index[c[k]] = static_cast<int>(out.positions.size());
        out.positions.push_back(point(c[k]));
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
