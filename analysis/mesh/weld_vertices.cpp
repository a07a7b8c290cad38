#include "analysis/mesh/weld_vertices.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "core/bounding_box.hpp"
#include "core/equal_points.hpp"
#include "core/union_find.hpp"

namespace cadnurbs {

namespace {

// A point and the cube it lies in (cube coordinates counted from the box's low corner, so never negative).
struct Entry {
  std::int32_t x, y, z;
  int point;
};

// Sorts entries given in increasing order of point by (x, y, z, point): a stable radix sort on 11-bit digits
// of z, then y, then x, skipping the digits all entries share. O(m) where a comparison sort is O(m log m).
void sort_by_cube(std::vector<Entry>& entries) {
  constexpr int kBits = 11, kDigits = 9;  // three digits a coordinate: 33 bits hold any int32 >= 0
  constexpr std::size_t kBuckets = std::size_t{1} << kBits;
  auto digit = [](const Entry& e, int d) -> std::size_t {
    const std::int32_t coordinate = d < 3 ? e.z : d < 6 ? e.y : e.x;
    return (static_cast<std::uint32_t>(coordinate) >> (kBits * (d % 3))) & (kBuckets - 1);
  };
  std::vector<std::array<std::uint32_t, kBuckets>> counts(kDigits);
  for (auto& count : counts) count.fill(0);
  for (const Entry& e : entries)
    for (int d = 0; d < kDigits; ++d) ++counts[d][digit(e, d)];
  std::vector<Entry> other;
  for (int d = 0; d < kDigits; ++d) {
    auto& count = counts[d];
    if (std::find(count.begin(), count.end(), static_cast<std::uint32_t>(entries.size())) != count.end()) continue;
    std::uint32_t sum = 0;
    for (std::uint32_t& c : count) sum += std::exchange(c, sum);  // each bucket's first place
    other.resize(entries.size());
    for (const Entry& e : entries) other[count[digit(e, d)]++] = e;
    entries.swap(other);
  }
}

// weld_vertices into `out`, which may be `mesh` itself: then its buffers are reused (triangles and corner
// normals compacted where they are; positions too when every distinct point is its own vertex and the
// kept vertices come in increasing order of their first input vertex).
void weld_into(const TriangleMesh& mesh, double tolerance, WeldReport* report, TriangleMesh& out) {
  if (!(tolerance >= 0) || !std::isfinite(tolerance))
    throw std::invalid_argument("weld_vertices: tolerance must be finite and >= 0, got " + std::to_string(tolerance));
  validate(mesh, "weld_vertices input");
  const std::size_t n = mesh.positions.size();
  // A soup (more vertices than triangles: an STL file read as it is repeats each corner about six times)
  // has its bitwise-equal vertices numbered first, in order of first occurrence, so that the distance
  // search sees each point once. Other meshes go to the search as they are: equal vertices are within
  // any tolerance of each other, so they are joined there, with the same classes, roots and positions.
  const bool soup = n > mesh.triangles.size();
  EqualPoints equal;
  std::vector<int> point_of_vertex;
  if (soup) {
    equal.reserve(n / 4);
    point_of_vertex.resize(n);
    for (std::size_t v = 0; v < n; ++v) point_of_vertex[v] = equal.add(mesh.positions[v]);
  }
  const std::vector<Eigen::Vector3d>& points = soup ? equal.points() : mesh.positions;
  const std::size_t m = points.size();
  auto point_of = [&](int v) { return soup ? point_of_vertex[v] : v; };

  const Eigen::AlignedBox3d box = mesh_bounding_box(mesh);
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
  std::vector<Entry> entries(m);
  for (std::size_t q = 0; q < m; ++q) {
    const Eigen::Vector3d c = ((points[q] - origin) / cell).array().floor();
    entries[q] = {static_cast<std::int32_t>(c.x()), static_cast<std::int32_t>(c.y()), static_cast<std::int32_t>(c.z()),
                  static_cast<int>(q)};
  }
  sort_by_cube(entries);
  auto cell_less = [](const Entry& a, const Entry& b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); };
  UnionFind classes(m);
  auto compare = [&](const Entry& a, const Entry& b) {
    if ((points[a.point] - points[b.point]).squaredNorm() <= tolerance2) classes.unite(a.point, b.point);
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
    r.largest_merge_distance = std::max(r.largest_merge_distance, (points[q] - points[root[q]]).norm());
  }
  classes = UnionFind();

  // A class's root is its smallest point, that of the class's first vertex in input order.
  const bool in_place = &out == &mesh;
  std::vector<int> index(m, -1);  // class root -> output vertex
  int vertices = 0;
  bool increasing = true;  // roots numbered in their own order
  int last_root = -1;
  const bool normals = mesh.corner_normals.size() == 3 * mesh.triangles.size() && !mesh.triangles.empty();
  const std::size_t triangles = mesh.triangles.size();
  if (!in_place) {
    out.triangles.reserve(triangles);
    if (normals) out.corner_normals.reserve(mesh.corner_normals.size());
  }
  std::size_t kept = 0;
  for (std::size_t t = 0; t < triangles; ++t) {
    const auto& tri = mesh.triangles[t];
    const std::array<int, 3> c{root[point_of(tri[0])], root[point_of(tri[1])], root[point_of(tri[2])]};
    if (c[0] == c[1] || c[1] == c[2] || c[2] == c[0]) {
      ++r.collapsed_triangles;
      continue;
    }
    const auto& a = points[c[0]];
    if ((points[c[1]] - a).cross(points[c[2]] - a).squaredNorm() == 0) {
      ++r.zero_area_triangles;
      continue;
    }
    std::array<int, 3> renumbered{};
    for (int k = 0; k < 3; ++k) {
      if (index[c[k]] < 0) {
        index[c[k]] = vertices++;
        increasing = increasing && c[k] > last_root;
        last_root = c[k];
      }
      renumbered[k] = index[c[k]];
    }
    if (in_place) {
      out.triangles[kept] = renumbered;
      if (normals)
        for (int k = 0; k < 3; ++k) out.corner_normals[3 * kept + k] = out.corner_normals[3 * t + k];
    } else {
      out.triangles.push_back(renumbered);
      if (normals)
        for (int k = 0; k < 3; ++k) out.corner_normals.push_back(mesh.corner_normals[3 * t + k]);
    }
    ++kept;
  }
  if (in_place) {
    out.triangles.resize(kept);
    if (normals) out.corner_normals.resize(3 * kept);
  }
  if (in_place && !soup && increasing) {
    // Each kept root moves to a place at or before its own, and no later root's place is written first.
    for (std::size_t q = 0; q < m; ++q)
      if (index[q] >= 0) out.positions[index[q]] = out.positions[q];
    out.positions.resize(vertices);
  } else {
    std::vector<Eigen::Vector3d> positions(vertices);
    for (std::size_t q = 0; q < m; ++q)
      if (index[q] >= 0) positions[index[q]] = points[q];
    out.positions = std::move(positions);
  }
  r.output_vertices = vertices;
  if (report) *report = r;
}

}  // namespace

double default_weld_tolerance(const TriangleMesh& mesh) {
  if (mesh.positions.empty()) return 0;
  return 1e-6 * mesh_bounding_box(mesh).diagonal().norm();
}

TriangleMesh weld_vertices(const TriangleMesh& mesh, double tolerance, WeldReport* report) {
  TriangleMesh out;
  weld_into(mesh, tolerance, report, out);
  return out;
}

TriangleMesh weld_vertices(TriangleMesh&& mesh, double tolerance, WeldReport* report) {
  weld_into(mesh, tolerance, report, mesh);
  return std::move(mesh);
}

}  // namespace cadnurbs
