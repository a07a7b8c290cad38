// orient_faces: flipped and inside-out cubes come out outward, two cubes are two components, a Moebius
// strip is one non-orientable component, duplicates are dropped; on the corpus STL files the crease
// normals then find no inconsistent edge in an orientable component and every closed one has volume > 0.
// The side partners handed out with the result are the result's own (flips and dropped duplicates moved).
#include "analysis/normals/orient_faces.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <random>

#include "analysis/normals/crease_normals.hpp"
#include "analysis/mesh/weld_vertices.hpp"
#include "core/worker_threads.hpp"
#include "formats/stl/stl_reader.hpp"
#include "weld_test_meshes.hpp"

namespace cadnurbs {
namespace {

TriangleMesh welded_cube(double size) {
  const TriangleMesh soup = test::stl_cube(size);
  return weld_vertices(soup, default_weld_tolerance(soup));
}

void flip(TriangleMesh& m, int t) { std::swap(m.triangles[t][0], m.triangles[t][1]); }

// The side partners orient_faces hands out are those of the mesh it returns.
void expect_partners_of(const SidePartners& given, const TriangleMesh& m, const char* what) {
  const SidePartners made = side_partners(m);
  EXPECT_EQ(given.partner, made.partner) << what;
  EXPECT_EQ(given.boundary_edges, made.boundary_edges) << what;
  EXPECT_EQ(given.non_manifold_edges, made.non_manifold_edges) << what;
}

// Six times the signed volume of the triangles for which keep(t) holds, from the origin.
template <class Keep>
double six_volume(const TriangleMesh& m, Keep keep) {
  double sum = 0;
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    if (keep(t)) {
      const auto& c = m.triangles[t];
      sum += m.positions[c[0]].dot(m.positions[c[1]].cross(m.positions[c[2]]));
    }
  return sum;
}

// Each triangle of a cube centred at `centre` must face along the axis its centroid lies farthest on.
void expect_outward_cube(const TriangleMesh& m, const Eigen::Vector3d& centre) {
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const auto& c = m.triangles[t];
    const auto& p = m.positions;
    const Eigen::Vector3d normal = (p[c[1]] - p[c[0]]).cross(p[c[2]] - p[c[0]]).normalized();
    const Eigen::Vector3d offset = (p[c[0]] + p[c[1]] + p[c[2]]) / 3 - centre;
    Eigen::Index axis = 0;
    offset.cwiseAbs().maxCoeff(&axis);
    Eigen::Vector3d expected = Eigen::Vector3d::Zero();
    expected[axis] = offset[axis] > 0 ? 1 : -1;
    EXPECT_LE((normal - expected).norm(), 1e-12) << "triangle " << t;
  }
}

TEST(OrientFaces, CubeWithFlippedTrianglesComesOutOutward) {
  TriangleMesh m = welded_cube(2.0);
  // Corner normals made distinguishable, to see that they follow their corners.
  for (std::size_t c = 0; c < m.corner_normals.size(); ++c) m.corner_normals[c] = Eigen::Vector3d(double(c), 0, 0);
  const TriangleMesh input = m;
  for (int t : {1, 4, 7}) flip(m, t);
  for (int t : {1, 4, 7}) std::swap(m.corner_normals[3 * t], m.corner_normals[3 * t + 1]);
  OrientReport report;
  const TriangleMesh oriented = orient_faces(m, &report);
  ASSERT_EQ(oriented.triangles.size(), 12u);
  expect_outward_cube(oriented, Eigen::Vector3d::Zero());
  EXPECT_EQ(report.flipped_triangles, 3);
  EXPECT_EQ(report.components, 1);
  EXPECT_EQ(report.closed_components, 1);
  EXPECT_EQ(report.non_orientable_components + report.inconsistent_edges + report.duplicate_triangles +
                report.boundary_edges + report.non_manifold_edges, 0);
  // Every corner keeps its own normal: (vertex, normal) pairs of each triangle as in the input.
  for (std::size_t t = 0; t < 12; ++t)
    for (int k = 0; k < 3; ++k) {
      const int v = oriented.triangles[t][k];
      int found = 0;
      for (int j = 0; j < 3; ++j)
        if (input.triangles[t][j] == v) found += oriented.corner_normals[3 * t + k] == input.corner_normals[3 * t + j];
      EXPECT_EQ(found, 1) << "triangle " << t << " corner " << k;
    }
}

TEST(OrientFaces, InsideOutCubeIsTurnedOutward) {
  const double size = 3.0;
  TriangleMesh m = welded_cube(size);
  for (int t = 0; t < 12; ++t) flip(m, t);
  EXPECT_NEAR(six_volume(m, [](std::size_t) { return true; }) / 6, -size * size * size, 1e-12);
  OrientReport report;
  const TriangleMesh oriented = orient_faces(m, &report);
  EXPECT_EQ(report.flipped_triangles, 12);
  EXPECT_EQ(report.closed_components, 1);
  EXPECT_NEAR(six_volume(oriented, [](std::size_t) { return true; }) / 6, size * size * size, 1e-12);
  expect_outward_cube(oriented, Eigen::Vector3d::Zero());
}

TEST(OrientFaces, TwoDisjointCubesOneInsideOut) {
  TriangleMesh m = welded_cube(2.0);
  TriangleMesh second = welded_cube(1.0);
  for (auto& p : second.positions) p += Eigen::Vector3d(10, 0, 0);
  for (int t = 0; t < 12; ++t) flip(second, t);
  flip(second, 5);  // and one of its triangles flipped back: inconsistent within the inside-out cube
  append(m, second);
  OrientReport report;
  std::vector<int> component;
  const TriangleMesh oriented = orient_faces(m, &report, &component);
  EXPECT_EQ(report.components, 2);
  EXPECT_EQ(report.closed_components, 2);
  EXPECT_EQ(report.flipped_triangles, 11);
  ASSERT_EQ(component.size(), 24u);
  for (int c : {0, 1}) {
    const double expected = c == 0 ? 8.0 : 1.0;
    EXPECT_NEAR(six_volume(oriented, [&](std::size_t t) { return component[t] == c; }) / 6, expected, 1e-12);
  }
  TriangleMesh first_cube = oriented, second_cube = oriented;
  first_cube.triangles.resize(12);
  second_cube.triangles.erase(second_cube.triangles.begin(), second_cube.triangles.begin() + 12);
  expect_outward_cube(first_cube, Eigen::Vector3d::Zero());
  expect_outward_cube(second_cube, Eigen::Vector3d(10, 0, 0));
}

// A strip of `segments` quads (two triangles each) around a circle, turned half a turn on the way: the
// last quad joins the first with top and bottom exchanged. No orientation is consistent; flooding from
// the first triangle leaves exactly one edge inconsistent (the strip's dual graph is one cycle).
TriangleMesh moebius_strip(int segments) {
  TriangleMesh m;
  for (int i = 0; i < segments; ++i) {
    const double a = 2 * std::numbers::pi * i / segments;
    const Eigen::Vector3d centre(5 * std::cos(a), 5 * std::sin(a), 0);
    const Eigen::Vector3d across =
        std::cos(a / 2) * Eigen::Vector3d(std::cos(a), std::sin(a), 0) + std::sin(a / 2) * Eigen::Vector3d::UnitZ();
    m.positions.push_back(centre + across);  // top i: 2i
    m.positions.push_back(centre - across);  // bottom i: 2i + 1
  }
  for (int i = 0; i < segments; ++i) {
    const bool last = i + 1 == segments;
    const int top = 2 * i, bottom = 2 * i + 1;
    const int next_top = last ? 1 : 2 * i + 2, next_bottom = last ? 0 : 2 * i + 3;
    m.triangles.push_back({top, bottom, next_bottom});
    m.triangles.push_back({top, next_bottom, next_top});
  }
  return m;
}

TEST(OrientFaces, MoebiusStripIsOneNonOrientableComponent) {
  const int segments = 12;
  const TriangleMesh m = moebius_strip(segments);
  OrientReport report;
  SidePartners partners;
  const TriangleMesh oriented = orient_faces(m, &report, nullptr, &partners);
  expect_partners_of(partners, oriented, "Moebius strip");
  EXPECT_GT(report.flipped_triangles, 0);
  EXPECT_EQ(report.components, 1);
  EXPECT_EQ(report.non_orientable_components, 1);
  EXPECT_EQ(report.inconsistent_edges, 1);
  EXPECT_EQ(report.closed_components, 0);
  EXPECT_EQ(report.boundary_edges, 2 * segments);  // one boundary loop, twice as long as the circle
  CreaseNormalsReport creases;
  with_crease_normals(oriented, 30 * std::numbers::pi / 180, &creases);
  EXPECT_EQ(creases.inconsistent_edges, 1);
}

TEST(OrientFaces, DuplicateTrianglesAreDropped) {
  TriangleMesh m = welded_cube(2.0);
  m.corner_normals.clear();
  const auto reversed = std::array<int, 3>{m.triangles[3][2], m.triangles[3][1], m.triangles[3][0]};
  m.triangles.push_back(reversed);                                                    // the other winding
  m.triangles.push_back({m.triangles[5][1], m.triangles[5][2], m.triangles[5][0]});   // the same, rotated
  m.triangles.push_back(m.triangles[5]);                                              // the same, verbatim
  OrientReport report;
  const TriangleMesh oriented = orient_faces(m, &report);
  EXPECT_EQ(report.duplicate_triangles, 3);
  ASSERT_EQ(oriented.triangles.size(), 12u);
  EXPECT_EQ(report.non_manifold_edges, 0);
  EXPECT_EQ(report.closed_components, 1);
  EXPECT_EQ(report.flipped_triangles, 0);
  expect_outward_cube(oriented, Eigen::Vector3d::Zero());
}

// Weld (default tolerance) and orient each corpus STL file; closedness checked by counting each
// component's edges here with a map, volume summed here.
TEST(OrientFaces, CorpusFilesOrientConsistentlyAndOutward) {
  const char* files[] = {"1002_tray_bottom.STL", "TR12J_OCC.stl", "bottle_ascii.stl", "fan.stl",
                         "featuretype.STL",      "motor.stl",     "plate_holes.STL",  "simple_mesh_binary.stl"};
  for (const char* file : files) {
    const TriangleMesh soup = read_stl(std::string(CADNURBS_SHARED_DIR) + "/corpus/stl/" + file);
    const TriangleMesh welded = weld_vertices(soup, default_weld_tolerance(soup));
    OrientReport report;
    std::vector<int> component;
    const TriangleMesh oriented = orient_faces(welded, &report, &component);
    EXPECT_EQ(oriented.triangles.size() + report.duplicate_triangles, welded.triangles.size()) << file;
    CreaseNormalsReport creases;
    with_crease_normals(oriented, 30 * std::numbers::pi / 180, &creases);
    EXPECT_EQ(creases.inconsistent_edges, report.inconsistent_edges) << file;
    if (report.non_orientable_components == 0) {
      EXPECT_EQ(creases.inconsistent_edges, 0) << file;
    }
    EXPECT_EQ(creases.boundary_edges, report.boundary_edges) << file;
    EXPECT_EQ(creases.non_manifold_edges, report.non_manifold_edges) << file;

    std::map<std::pair<int, int>, int> faces_at_edge;
    for (const auto& c : oriented.triangles)
      for (int k = 0; k < 3; ++k) ++faces_at_edge[std::minmax(c[k], c[(k + 1) % 3])];
    std::vector<char> closed(report.components, 1);
    std::vector<char> orientable(report.components, 1);
    std::map<std::pair<int, int>, std::vector<int>> directed;  // consistent: no directed edge twice
    for (std::size_t t = 0; t < oriented.triangles.size(); ++t) {
      const auto& c = oriented.triangles[t];
      for (int k = 0; k < 3; ++k) {
        if (faces_at_edge[std::minmax(c[k], c[(k + 1) % 3])] != 2) closed[component[t]] = 0;
        directed[{c[k], c[(k + 1) % 3]}].push_back(static_cast<int>(t));
      }
    }
    int same_way = 0;
    for (const auto& [edge, triangles] : directed)
      if (triangles.size() == 2 && faces_at_edge[std::minmax(edge.first, edge.second)] == 2) {
        ++same_way;
        orientable[component[triangles[0]]] = 0;
      }
    EXPECT_EQ(same_way, report.inconsistent_edges) << file;
    int closed_count = 0, positive = 0;
    double smallest = INFINITY;
    for (int c = 0; c < report.components; ++c) {
      closed_count += closed[c];
      if (!closed[c] || !orientable[c]) continue;
      const double volume = six_volume(oriented, [&](std::size_t t) { return component[t] == c; }) / 6;
      positive += volume > 0;
      smallest = std::min(smallest, volume);
      EXPECT_GT(volume, 0) << file << " component " << c;
    }
    EXPECT_EQ(closed_count, report.closed_components) << file;

    // Every third triangle turned over: orienting again restores each closed component exactly, each open
    // one up to turning it over whole.
    TriangleMesh scrambled = welded;
    for (std::size_t t = 0; t < scrambled.triangles.size(); t += 3) std::swap(scrambled.triangles[t][0], scrambled.triangles[t][1]);
    // Duplicates too, one winding or the other, so that flips and dropped triangles both move the sides.
    scrambled.corner_normals.clear();
    for (std::size_t t = 0; t < welded.triangles.size(); t += 5)
      scrambled.triangles.push_back(t % 2 ? scrambled.triangles[t] : std::array{scrambled.triangles[t][1],
                                                                               scrambled.triangles[t][0],
                                                                               scrambled.triangles[t][2]});
    OrientReport again;
    SidePartners partners;
    const TriangleMesh restored = orient_faces(scrambled, &again, nullptr, &partners);
    expect_partners_of(partners, restored, file);
    CreaseNormalsReport given_report, made_report;
    const CornerNormals given = crease_normals(restored, 30 * std::numbers::pi / 180, &given_report, &partners);
    const CornerNormals made = crease_normals(restored, 30 * std::numbers::pi / 180, &made_report);
    EXPECT_EQ(given.normals, made.normals) << file;
    EXPECT_EQ(given.corner_normal, made.corner_normal) << file;
    EXPECT_EQ(given_report.smooth_edges, made_report.smooth_edges) << file;
    ASSERT_EQ(restored.triangles.size(), oriented.triangles.size()) << file;
    EXPECT_GT(again.flipped_triangles, 0) << file;
    std::vector<int> same(report.components, 0), reversed(report.components, 0);
    for (std::size_t t = 0; t < restored.triangles.size(); ++t) {
      auto a = restored.triangles[t];
      const auto& b = oriented.triangles[t];
      while (a[0] != b[0]) std::rotate(a.begin(), a.begin() + 1, a.end());
      ++(a == b ? same : reversed)[component[t]];
    }
    int wrong = 0;
    for (int c = 0; c < report.components; ++c) wrong += closed[c] ? reversed[c] : std::min(same[c], reversed[c]);
    EXPECT_EQ(wrong, 0) << file;
    std::printf("%-24s triangles %7zu  components %4d  closed %4d (volume > 0: %4d, smallest %.4g)  flipped %6d  "
                "non-orientable %d (%d edges)  duplicates %d  non-manifold %d  boundary %d\n",
                file, oriented.triangles.size(), report.components, report.closed_components, positive, smallest,
                report.flipped_triangles, report.non_orientable_components, report.inconsistent_edges,
                report.duplicate_triangles, report.non_manifold_edges, report.boundary_edges);
  }
}


// The duplicate test, the side partners and the flood are shared out to worker threads by vertex and
// triangle ranges: any count gives the same mesh, report, components and partners. The triangles are
// shuffled, so that each range holds many pieces of each component, and some turned over; one mesh is
// orientable (the ranges' pieces joined), the other holds a Moebius strip too (flooded again in one range).
TEST(OrientFaces, AnyThreadCountGivesTheSameResult) {
  TriangleMesh orientable;
  for (int i = 0; i < 3; ++i) {
    TriangleMesh cube = welded_cube(1.0 + i);
    for (auto& p : cube.positions) p.x() += 10 * i;
    append(orientable, cube);
  }
  const int n = 40;  // an open grid of n x n quads
  TriangleMesh grid;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) grid.positions.emplace_back(i, j, 50 + std::sin(0.3 * i + 0.2 * j));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const int a = i * (n + 1) + j;
      grid.triangles.push_back({a, a + n + 1, a + n + 2});
      grid.triangles.push_back({a, a + n + 2, a + 1});
    }
  grid.triangles.push_back({0, n + 2, static_cast<int>(grid.positions.size())});  // a fin on a diagonal: non-manifold
  grid.positions.emplace_back(0, 0.5, 60);
  append(orientable, grid);
  TriangleMesh with_strip = orientable;
  append(with_strip, moebius_strip(30));
  for (TriangleMesh* m : {&orientable, &with_strip}) {
    m->corner_normals.clear();
    m->triangles.push_back(m->triangles[7]);  // a duplicate
    std::mt19937 random(11);
    std::shuffle(m->triangles.begin(), m->triangles.end(), random);
    for (std::size_t t = 0; t < m->triangles.size(); t += 3) std::swap(m->triangles[t][0], m->triangles[t][1]);
  }
  for (const TriangleMesh* m : {&orientable, &with_strip}) {
    set_worker_threads(1);
    OrientReport one_report;
    std::vector<int> one_component;
    SidePartners one_partners;
    const TriangleMesh one = orient_faces(*m, &one_report, &one_component, &one_partners);
    EXPECT_EQ(one_report.duplicate_triangles, 1);
    EXPECT_EQ(one_report.non_manifold_edges, 1);
    EXPECT_EQ(one_report.components, m == &orientable ? 5 : 6);  // the fin is a component of its own
    EXPECT_EQ(one_report.non_orientable_components, m == &orientable ? 0 : 1);
    EXPECT_EQ(one_report.closed_components, 3);
    EXPECT_GT(one_report.flipped_triangles, 0);
    expect_partners_of(one_partners, one, "one thread");
    for (const int threads : {2, 3, 7, 8}) {
      set_worker_threads(threads);
      OrientReport report;
      std::vector<int> component;
      SidePartners partners;
      const TriangleMesh oriented = orient_faces(*m, &report, &component, &partners);
      EXPECT_EQ(oriented.triangles, one.triangles) << threads << " threads";
      EXPECT_EQ(component, one_component) << threads << " threads";
      EXPECT_EQ(partners.partner, one_partners.partner) << threads << " threads";
      EXPECT_EQ(partners.boundary_edges, one_partners.boundary_edges) << threads << " threads";
      EXPECT_EQ(partners.non_manifold_edges, one_partners.non_manifold_edges) << threads << " threads";
      EXPECT_EQ(report.components, one_report.components) << threads << " threads";
      EXPECT_EQ(report.closed_components, one_report.closed_components) << threads << " threads";
      EXPECT_EQ(report.flipped_triangles, one_report.flipped_triangles) << threads << " threads";
      EXPECT_EQ(report.non_orientable_components, one_report.non_orientable_components) << threads << " threads";
      EXPECT_EQ(report.inconsistent_edges, one_report.inconsistent_edges) << threads << " threads";
      EXPECT_EQ(report.duplicate_triangles, one_report.duplicate_triangles) << threads << " threads";
    }
  }
  set_worker_threads(0);
}

}  // namespace
}  // namespace cadnurbs
