// weld_vertices: the STL cube, exactness at grid-cell borders, chains, a brute-force reference, and the
// corpus STL files against OpenMesh's STL reader (which merges equal float coordinates).
#include "analysis/mesh/weld_vertices.hpp"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <gtest/gtest.h>

#include <cstdio>
#include <numeric>
#include <random>
#include <set>

#include "formats/common/file_io.hpp"
#include "formats/stl/stl_reader.hpp"
#include "weld_test_meshes.hpp"

namespace cadnurbs {
namespace {

// A soup of two triangles (6 vertices) whose first corners are the given points.
TriangleMesh two_triangles(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  TriangleMesh m;
  m.positions = {a, a + Eigen::Vector3d(10, 0, 0), a + Eigen::Vector3d(0, 10, 0),
                 b, b + Eigen::Vector3d(0, 0, 10), b + Eigen::Vector3d(10, 10, 10)};
  m.triangles = {{0, 1, 2}, {3, 4, 5}};
  return m;
}

TEST(WeldVertices, StlCubeWeldsTo8Vertices) {
  const TriangleMesh soup = test::stl_cube(2.0);
  ASSERT_EQ(soup.positions.size(), 36u);
  WeldReport report;
  const TriangleMesh welded = weld_vertices(soup, default_weld_tolerance(soup), &report);
  EXPECT_EQ(welded.positions.size(), 8u);
  EXPECT_EQ(welded.triangles.size(), 12u);
  EXPECT_EQ(welded.corner_normals.size(), 36u);  // followed their triangles
  EXPECT_EQ(report.vertex_classes, 8);
  EXPECT_EQ(report.collapsed_triangles, 0);
  EXPECT_EQ(report.largest_merge_distance, 0.0);
  EXPECT_DOUBLE_EQ(default_weld_tolerance(soup), 1e-6 * std::sqrt(12.0));
}

// Points 0.9 x tolerance apart straddling a cell border (the grid starts at the bounding box's
// minimum, the origin here, with cells a hair wider than the tolerance) along one axis and along all
// three at once; 1.1 x apart they stay two.
TEST(WeldVertices, PairAcrossCellBorderMergesExactlyWithinTolerance) {
  const double tol = 0.01;
  const Eigen::Vector3d border(5 * tol, 5 * tol, 5 * tol);
  const Eigen::Vector3d diagonal = Eigen::Vector3d::Ones().normalized();
  for (const Eigen::Vector3d& direction : {Eigen::Vector3d(Eigen::Vector3d::UnitX()), diagonal}) {
    for (double factor : {0.9, 1.1}) {
      const Eigen::Vector3d half = 0.5 * factor * tol * direction;
      TriangleMesh m = two_triangles(border - half, border + half);
      m.positions.push_back(Eigen::Vector3d::Zero());  // puts the grid origin at 0
      m.triangles.push_back({6, 1, 2});
      WeldReport report;
      weld_vertices(m, tol, &report);
      EXPECT_EQ(report.vertex_classes, factor < 1 ? 6 : 7) << "factor " << factor << " direction " << direction.transpose();
    }
  }
}

TEST(WeldVertices, ChainsMergeTransitively) {
  const double tol = 1.0;
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {0.9, 0, 0}, {1.8, 0, 0}, {0, 50, 0}, {0, 0, 50}};
  m.triangles = {{0, 3, 4}, {1, 3, 4}, {2, 3, 4}};
  WeldReport report;
  const TriangleMesh welded = weld_vertices(m, tol, &report);
  EXPECT_EQ(report.vertex_classes, 3);
  EXPECT_EQ(welded.positions.size(), 3u);
  ASSERT_EQ(welded.triangles.size(), 3u);  // three copies of one triangle: duplicates are not collapsed
  for (const auto& t : welded.triangles) EXPECT_EQ(t, (std::array<int, 3>{0, 1, 2}));
  EXPECT_EQ(report.collapsed_triangles, 0);
  EXPECT_DOUBLE_EQ(report.largest_merge_distance, 1.8);  // beyond the tolerance: the chain shows
  EXPECT_EQ(welded.positions[0], Eigen::Vector3d(0, 0, 0));  // the first vertex's position
}

TEST(WeldVertices, DropsCollapsedAndZeroAreaTriangles) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1e-9, 0, 0}, {2, 0, 0}};
  m.triangles = {{0, 1, 2}, {0, 3, 2}, {0, 1, 4}};  // second collapses (0 ~ 3), third is collinear
  m.corner_normals.assign(9, Eigen::Vector3d::UnitZ());
  WeldReport report;
  const TriangleMesh welded = weld_vertices(m, 1e-6, &report);
  EXPECT_EQ(welded.triangles.size(), 1u);
  EXPECT_EQ(welded.corner_normals.size(), 3u);
  EXPECT_EQ(report.collapsed_triangles, 1);
  EXPECT_EQ(report.zero_area_triangles, 1);
  EXPECT_EQ(report.vertex_classes, 4);
  EXPECT_EQ(report.output_vertices, 3);  // vertex 4 only in the dropped collinear triangle
  EXPECT_THROW(weld_vertices(m, -1, nullptr), std::invalid_argument);
}

// Union-find over all pairs (O(n^2)) on clustered random points: the same partition.
TEST(WeldVertices, MatchesBruteForcePartition) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0, 1);
  TriangleMesh m;
  const int n = 3000;
  for (int i = 0; i < n; ++i) m.positions.emplace_back(unit(random), unit(random), unit(random));
  for (int i = 0; i + 2 < n; i += 3) m.triangles.push_back({i, i + 1, i + 2});
  const double tol = 0.03;  // about 0.34 neighbours per point: many small clusters and some chains
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int i) {
    while (parent[i] != i) i = parent[i];
    return i;
  };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < i; ++j)
      if ((m.positions[i] - m.positions[j]).norm() <= tol) parent[root(i)] = root(j);
  int classes = 0;
  for (int i = 0; i < n; ++i) classes += root(i) == i;
  WeldReport report;
  weld_vertices(m, tol, &report);
  EXPECT_EQ(report.vertex_classes, classes);
  EXPECT_LT(classes, n - 100);  // the test merges something
}

// The in-place weld (a mesh moved in) gives what the copying one gives, also where the kept vertices come
// out of their input order (a dropped first triangle, chains merged into a later vertex) so that the
// positions cannot be compacted where they are, and on indexed meshes where equal vertices are left to the
// distance sweep rather than numbered first.
TEST(WeldVertices, InPlaceWeldGivesTheCopyingWeldsMesh) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0, 1);
  std::uniform_int_distribution<int> pick(0, 999);
  TriangleMesh m;
  for (int i = 0; i < 1000; ++i) m.positions.emplace_back(unit(random), unit(random), unit(random));
  for (int i = 0; i < 200; ++i) m.positions.push_back(m.positions[pick(random)]);  // bitwise repeats
  m.triangles.push_back({1100, 1101, 1101});  // collapsed: the first vertices used are late ones
  for (int i = 0; i < 3000; ++i) {
    const int a = pick(random), b = pick(random) + 200 * (i % 2), c = pick(random);
    if (a != b && b != c && c != a) m.triangles.push_back({a, b, c});
  }
  for (std::size_t c = 0; c < 3 * m.triangles.size(); ++c) m.corner_normals.emplace_back(c, 0, 1);
  for (const double tolerance : {0.0, 0.01, 0.04}) {
    WeldReport copying, in_place;
    const TriangleMesh expected = weld_vertices(m, tolerance, &copying);
    const TriangleMesh welded = weld_vertices(TriangleMesh(m), tolerance, &in_place);
    EXPECT_EQ(welded.positions, expected.positions) << tolerance;
    EXPECT_EQ(welded.triangles, expected.triangles) << tolerance;
    EXPECT_EQ(welded.corner_normals, expected.corner_normals) << tolerance;
    EXPECT_EQ(in_place.vertex_classes, copying.vertex_classes) << tolerance;
    EXPECT_EQ(in_place.output_vertices, copying.output_vertices) << tolerance;
    EXPECT_EQ(in_place.collapsed_triangles, copying.collapsed_triangles) << tolerance;
    EXPECT_EQ(in_place.largest_merge_distance, copying.largest_merge_distance) << tolerance;
    EXPECT_LE(copying.vertex_classes, 1000) << tolerance;  // the repeats at least are merged
    EXPECT_GE(copying.collapsed_triangles, 1) << tolerance;
  }
}

// OpenMesh's STL reader merges vertices with equal float coordinates; where a triangle cannot join its
// half-edge mesh (a non-manifold "complex vertex") its importer adds the triangle on copies of its
// vertices, so the reference count is OpenMesh's distinct points, not n_vertices(). Our reader widens
// float32 to double, so an exact weld (tolerance 0) must give that count; the default tolerance may
// merge a little more.
TEST(WeldVertices, CorpusCountsAgreeWithOpenMesh) {
  const char* files[] = {"1002_tray_bottom.STL", "TR12J_OCC.stl", "bottle_ascii.stl", "fan.stl",
                         "featuretype.STL",      "motor.stl",     "plate_holes.STL",  "simple_mesh_binary.stl"};
  for (const char* file : files) {
    const std::string path = std::string(CADNURBS_SHARED_DIR) + "/corpus/stl/" + file;
    const TriangleMesh soup = read_stl(path);
    WeldReport exact, relative;
    weld_vertices(soup, 0.0, &exact);
    weld_vertices(soup, default_weld_tolerance(soup), &relative);
    OpenMesh::TriMesh_ArrayKernelT<> reference;
    ::omerr().disable();  // one "complex vertex" line per copied triangle
    ASSERT_TRUE(OpenMesh::IO::read_mesh(reference, path)) << path;
    ::omerr().enable();
    std::set<std::array<float, 3>> points;
    for (const auto& v : reference.vertices()) {
      const auto& p = reference.point(v);
      points.insert({p[0], p[1], p[2]});
    }
    std::printf("%-24s triangles %7zu  OpenMesh vertices %7zu (distinct %7zu)  weld 0: %7d  weld 1e-6 diag: %7d (dropped %d, moved <= %.2g diag)\n",
                file, soup.triangles.size(), reference.n_vertices(), points.size(), exact.vertex_classes,
                relative.vertex_classes, relative.collapsed_triangles + relative.zero_area_triangles,
                relative.largest_merge_distance / (1e6 * default_weld_tolerance(soup)));
    EXPECT_EQ(static_cast<size_t>(exact.vertex_classes), points.size()) << file;
  }
}

// read_stl's block-wise binary reading gives what parse_stl gives on the whole file; with equal corners
// merged while reading, the weld gives bit for bit the mesh it gives from the soup (the path of
// bench_normals), and without facet normals no corner normals.
TEST(WeldVertices, CorpusMergedReadWeldsAsTheSoup) {
  const char* files[] = {"1002_tray_bottom.STL", "TR12J_OCC.stl", "bottle_ascii.stl", "fan.stl",
                         "featuretype.STL",      "motor.stl",     "plate_holes.STL",  "simple_mesh_binary.stl"};
  auto same = [](const TriangleMesh& a, const TriangleMesh& b) {
    return a.positions == b.positions && a.triangles == b.triangles && a.corner_normals == b.corner_normals;
  };
  for (const char* file : files) {
    const std::string path = std::string(CADNURBS_SHARED_DIR) + "/corpus/stl/" + file;
    const TriangleMesh soup = read_stl(path);
    EXPECT_TRUE(same(soup, parse_stl(read_file(path), path))) << file;
    const TriangleMesh merged = read_stl(path, {.merge_equal_points = true});
    const TriangleMesh bare = read_stl(path, {.facet_normals = false, .merge_equal_points = true});
    EXPECT_EQ(merged.triangles.size(), soup.triangles.size()) << file;
    EXPECT_LT(merged.positions.size(), soup.positions.size() / 3) << file;
    EXPECT_TRUE(bare.corner_normals.empty()) << file;
    for (const double tolerance : {0.0, default_weld_tolerance(soup), 1e3 * default_weld_tolerance(soup)}) {
      WeldReport from_soup, from_merged;
      const TriangleMesh expected = weld_vertices(soup, tolerance, &from_soup);
      EXPECT_TRUE(same(weld_vertices(merged, tolerance, &from_merged), expected)) << file << " at " << tolerance;
      EXPECT_EQ(from_merged.vertex_classes, from_soup.vertex_classes) << file;
      EXPECT_EQ(from_merged.largest_merge_distance, from_soup.largest_merge_distance) << file;
      EXPECT_EQ(weld_vertices(bare, tolerance).positions, expected.positions) << file;
      WeldReport in_place_report;
      EXPECT_TRUE(same(weld_vertices(TriangleMesh(merged), tolerance, &in_place_report), expected)) << file;
      EXPECT_EQ(in_place_report.largest_merge_distance, from_merged.largest_merge_distance) << file;
      EXPECT_TRUE(same(weld_vertices(TriangleMesh(soup), tolerance), expected)) << file;
    }
  }
}

}  // namespace
}  // namespace cadnurbs
