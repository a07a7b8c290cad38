// Traversal-coded triangle meshes (.cnb shape kind 5): every kind of mesh decodes to the same oriented
// triangles on the grid (a torus, whose handles make the border join lists; open sheets; several
// components; non-manifold edges and vertices; a flipped triangle), vertices move by at most q·√3/2,
// meshes with normals keep the plain coding, and on a corpus part's certified mesh the file is smaller
// than Draco's at the same vertex budget.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <random>

#include "analysis/mesh/count_boundary_edges.hpp"
#include "analysis/mesh/scene_triangles.hpp"
#include "analysis/mesh/oriented_triangle_keys.hpp"
#include "analysis/mesh/weld_exact.hpp"
#include "analysis/measure/mesh_distance.hpp"
#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "core/bounding_box.hpp"
#include "core/flatten_transforms.hpp"
#include "formats/cnb/adaptive_arithmetic_coder.hpp"
#include "formats/cnb/cnb_reader.hpp"
#include "formats/cnb/cnb_stream.hpp"
#include "formats/cnb/cnb_writer.hpp"
#include "formats/draco/draco_mesh_codec.hpp"
#include "formats/common/file_io.hpp"
#include "formats/step/step_reader.hpp"
#include "tests/cnb/expect_same_mesh_on_grid.hpp"
#include "tests/cnb/cnb_file_header.hpp"

namespace cadnurbs {
namespace {

Scene scene_of(const TriangleMesh& mesh) {
  Scene scene;
  scene.root.name = "meshes";
  scene.root.shapes.push_back({"mesh", mesh, std::nullopt});
  return scene;
}

struct Decoded {
  std::string bytes;
  TriangleMesh mesh;
  double step = 0;
};

// Every vertex at its nearest grid point (CnbOptions::free_mesh_points off), so that the triangles can be
// compared by position.
Decoded round_trip(const TriangleMesh& mesh, double deviation) {
  CnbOptions options;
  options.max_deviation = deviation;
  options.free_mesh_points = false;
  CnbWriteReport report;
  Decoded d;
  d.bytes = write_cnb(scene_of(mesh), options, &report);
  d.step = report.point_step;
  const Scene scene = read_cnb(d.bytes, "mesh.cnb");
  d.mesh = std::get<TriangleMesh>(scene.root.shapes.at(0).geometry);
  return d;
}

// The decoded triangles are the input's, with every corner on the grid where rounding puts it.
void expect_same_triangles(const TriangleMesh& mesh, const Decoded& d) {
  const TriangleMesh on_grid = mesh_on_grid(mesh, d.step);
  ASSERT_EQ(d.mesh.triangles.size(), mesh.triangles.size());
  EXPECT_EQ(oriented_triangle_keys(d.mesh.positions, d.mesh.triangles),
            oriented_triangle_keys(on_grid.positions, on_grid.triangles));
  for (size_t i = 0; i < on_grid.positions.size(); ++i)
    EXPECT_LE((on_grid.positions[i] - mesh.positions[i]).norm(), d.step * std::sqrt(3.0) / 2 * (1 + 1e-12));
}

// A torus of n x m quads, two triangles each: closed, genus 1.
TriangleMesh torus(int n, int m) {
  TriangleMesh mesh;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double u = 2 * std::numbers::pi * i / n, v = 2 * std::numbers::pi * j / m;
      mesh.positions.emplace_back((10 + 3 * std::cos(v)) * std::cos(u), (10 + 3 * std::cos(v)) * std::sin(u),
                                  3 * std::sin(v));
    }
  auto at = [&](int i, int j) { return ((i + n) % n) * m + (j + m) % m; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return mesh;
}

// A flat n x n sheet of unit squares, offset by `origin` (an open mesh: its border is a boundary).
void add_sheet(TriangleMesh& mesh, int n, const Eigen::Vector3d& origin) {
  const int first = static_cast<int>(mesh.positions.size());
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) mesh.positions.push_back(origin + Eigen::Vector3d(i, j, 0));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const int a = first + i * (n + 1) + j, b = a + n + 1;
      mesh.triangles.push_back({a, b, b + 1});
      mesh.triangles.push_back({a, b + 1, a + 1});
    }
}

TEST(CnbTraversalMesh, TorusDecodesToTheSameTriangles) {
  const TriangleMesh mesh = torus(24, 12);
  const Decoded d = round_trip(mesh, 0.01);
  expect_same_triangles(mesh, d);
  EXPECT_EQ(d.mesh.positions.size(), mesh.positions.size());
}

TEST(CnbTraversalMesh, SheetsComponentsAndNonManifoldPlaces) {
  TriangleMesh mesh;
  add_sheet(mesh, 6, {0, 0, 0});
  add_sheet(mesh, 3, {20, 0, 0});
  // A third triangle on one edge of the first sheet (a non-manifold edge), and one on another edge but
  // flipped against its neighbour.
  mesh.positions.emplace_back(0.5, 0.5, 4);
  mesh.triangles.push_back({0, 7, static_cast<int>(mesh.positions.size()) - 1});
  mesh.positions.emplace_back(6.5, 3.5, -2);
  mesh.triangles.push_back({48, 41, static_cast<int>(mesh.positions.size()) - 1});
  // Two tetrahedra touching at one vertex (a non-manifold vertex).
  const int apex = static_cast<int>(mesh.positions.size());
  mesh.positions.emplace_back(40, 0, 0);
  for (double side : {1.0, -1.0}) {
    const int b = static_cast<int>(mesh.positions.size());
    mesh.positions.emplace_back(40 + side, 0, 1);
    mesh.positions.emplace_back(40 + side, 1, -1);
    mesh.positions.emplace_back(40 + side, -1, -1);
    for (auto t :
         std::vector<std::array<int, 3>>{{apex, b, b + 1}, {apex, b + 1, b + 2}, {apex, b + 2, b}, {b, b + 2, b + 1}})
      mesh.triangles.push_back(side > 0 ? t : std::array<int, 3>{t[0], t[2], t[1]});
  }
  const Decoded d = round_trip(mesh, 0.001);
  expect_same_triangles(mesh, d);
}

TEST(CnbTraversalMesh, UnusedVerticesAreNotKeptAndNormalsKeepThePlainCoding) {
  TriangleMesh mesh;
  add_sheet(mesh, 2, {0, 0, 0});
  mesh.positions.emplace_back(100, 100, 100);  // no triangle uses it
  const Decoded d = round_trip(mesh, 0.01);
  EXPECT_EQ(d.mesh.positions.size(), 9u);
  expect_same_triangles(mesh, d);

  TriangleMesh with_normals = mesh;
  with_normals.corner_normals.assign(3 * mesh.triangles.size(), Eigen::Vector3d(0, 0, 1));
  const Decoded plain = round_trip(with_normals, 0.01);
  EXPECT_EQ(plain.mesh.positions.size(), 10u);  // the plain coding keeps every vertex, in order
  EXPECT_EQ(plain.mesh.corner_normals.size(), with_normals.corner_normals.size());
}

// Version 3 coded mesh symbols in two contexts (after a new vertex, after anything else) and each vertex
// coordinate's first byte in its field's one; version 4 by the symbol before and by axis. A version 3 file,
// made from a version 8 payload without vertex predictors, with its contexts mapped back and the mesh's
// period (version 5; zero for a torus whose points are jittered off its symmetries; in version 8 its x
// also says that no predictors are named) left out, still reads to the same mesh; read as version 4, the
// same bytes do not.
TEST(CnbTraversalMesh, VersionThreeContextsStillRead) {
  CnbOptions options;
  options.max_deviation = 0.01;
  options.coder = CnbOptions::Coder::arithmetic;
  options.vertex_predictors = false;
  options.gate_shapes = false;  // a version 8 file
  TriangleMesh jittered = torus(24, 12);
  std::mt19937 random(5);
  for (auto& p : jittered.positions)
    for (int k = 0; k < 3; ++k) p[k] += 0.1 * (static_cast<double>(random() % 1000) / 1000 - 0.5);
  const std::string v4 = write_cnb(scene_of(jittered), options);
  CnbPayload payload = read_cnb_payload(v4, "torus.cnb");
  cnb::ByteWriter period;  // the period's context: the only NURBS point field of a mesh's file
  period.varsint(0, cnb::Field::point);
  std::string bytes;
  std::vector<uint8_t> kept;
  for (size_t i = 0; i < payload.bytes.size(); ++i)
    if (payload.contexts[i] == period.contexts()[0])
      ASSERT_EQ(payload.bytes[i], 0) << "the jittered torus has no period, and names no predictors";
    else
      bytes.push_back(payload.bytes[i]), kept.push_back(payload.contexts[i]);
  ASSERT_EQ(bytes.size() + 3, payload.bytes.size());
  payload.bytes = bytes;
  payload.contexts = kept;
  cnb::ByteWriter old_symbol;  // version 3's symbol contexts: after a new vertex, after anything else
  old_symbol.byte(0, cnb::Field::symbol, false);
  old_symbol.byte(0, cnb::Field::symbol, true);
  std::vector<uint8_t> contexts = payload.contexts;
  for (auto& c : contexts) {
    for (int s = 0; s < cnb::mesh_symbol_count; ++s)
      if (c == cnb::symbol_context(static_cast<uint8_t>(s))) c = old_symbol.contexts()[s == 0 ? 0 : 1];
    for (auto field : {cnb::Field::mesh_rank, cnb::Field::mesh_point})
      for (int axis = 1; axis < 3; ++axis)
        if (c == cnb::axis_context(field, axis)) c = static_cast<uint8_t>(cnb::axis_context(field, 0));
  }
  const std::string coded = cnb::arithmetic_encode(payload.bytes, contexts, cnb::uniform_models(), cnb::Adaptation::one_rate);
  const size_t coded_at = crc_offset(v4) + 4;
  ASSERT_NE(coded, v4.substr(coded_at));  // the contexts change the coding
  const std::string v3 = with_version(with_payload_size(v4.substr(0, coded_at) + coded, bytes.size()), 3);
  const auto mesh_of = [](const std::string& file) {
    return std::get<TriangleMesh>(read_cnb(file, "torus.cnb").root.shapes.at(0).geometry);
  };
  const TriangleMesh written = mesh_of(v4), old = mesh_of(v3);
  EXPECT_EQ(old.positions, written.positions);
  EXPECT_EQ(old.triangles, written.triangles);
  bool same_as_version_4 = false;
  try {
    const TriangleMesh misread = mesh_of(with_version(v3, 4));
    same_as_version_4 = misread.positions == written.positions && misread.triangles == written.triangles;
  } catch (const FileError&) {
  }
  EXPECT_FALSE(same_as_version_4);
}

// Arbitrary triangle sets (shared corners in every way a soup allows: edges used by one, two or many
// triangles, in either direction) still decode to the same triangles.
TEST(CnbTraversalMesh, RandomTriangleSetsDecodeToTheSameTriangles) {
  std::mt19937 random(39);
  for (int trial = 0; trial < 300; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    TriangleMesh mesh;
    const int vertices = 4 + static_cast<int>(random() % 20);
    for (int i = 0; i < vertices; ++i) mesh.positions.emplace_back(random() % 50, random() % 50, random() % 50);
    const int triangles = 1 + static_cast<int>(random() % 60);
    while (static_cast<int>(mesh.triangles.size()) < triangles) {
      const std::array<int, 3> t{static_cast<int>(random() % vertices), static_cast<int>(random() % vertices),
                                 static_cast<int>(random() % vertices)};
      if (t[0] != t[1] && t[1] != t[2] && t[2] != t[0]) mesh.triangles.push_back(t);
    }
    expect_same_triangles(mesh, round_trip(mesh, 0.1));
  }
}

// A flat sheet's parallelograms predict every new vertex exactly: well under a byte per triangle.
TEST(CnbTraversalMesh, FlatSheetCostsLittle) {
  TriangleMesh mesh;
  add_sheet(mesh, 40, {0, 0, 0});
  const Decoded d = round_trip(mesh, 0.01);
  expect_same_triangles(mesh, d);
  std::cout << mesh.triangles.size() << " triangles, " << mesh.positions.size() << " vertices: " << d.bytes.size()
            << " bytes\n";
  EXPECT_LT(d.bytes.size(), mesh.triangles.size() / 4);
}

// A corpus STEP part's certified mesh (welded, without normals) within share·D, D = diagonal_fraction of
// its diagonal, and the writer's options for it: D, the share for meshes and the mesh's certificate.
struct CertifiedPartMesh {
  TriangleMesh mesh;
  CnbOptions options;
};
CertifiedPartMesh certified_part_mesh(const std::string& corpus_path, double diagonal_fraction, double share) {
  const Scene part = read_step(std::string(CADNURBS_SHARED_DIR) + "/corpus/" + corpus_path).scene;
  const double d = diagonal_fraction * scene_bounding_box(part).diagonal().norm();
  CertifiedPartMesh c;
  c.mesh = weld_exact(scene_triangles(tessellate_to_deviation(flatten_transforms(part), share * d)));
  c.mesh.corner_normals.clear();
  c.options.max_deviation = d;
  c.options.trim_share = share;
  c.options.mesh_deviation = share * d;
  return c;
}

// The distance from each point of `points` to the nearest of `others`, the largest (brute force).
double largest_nearest_distance(const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector3d>& others) {
  double largest = 0;
  for (const auto& p : points) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& o : others) nearest = std::min(nearest, (o - p).squaredNorm());
    largest = std::max(largest, std::sqrt(nearest));
  }
  return largest;
}

// Where it codes smaller, a new vertex takes, instead of its nearest grid point, the grid point within the
// points' bound that lies nearest its prediction in bits: on linkrods.step's certified mesh at 3e-4 of its
// diagonal (a dense mesh of curved faces, where Draco had been smaller). Every vertex stays within the
// bound, the triangles and the closed mesh stay as they were.
TEST(CnbTraversalMesh, VerticesMayTakeACheaperGridPointWithinTheBound) {
  const auto [mesh, options] = certified_part_mesh("step/linkrods.step", 3e-4, 0.6);
  const double d = options.max_deviation;
  CnbWriteReport report;
  const std::string bytes = write_cnb(scene_of(mesh), options, &report);
  EXPECT_GT(report.vertices_off_nearest, static_cast<long>(mesh.positions.size() / 10));
  EXPECT_LE(report.deviation_bound(), d * (1 + 1e-12));
  const TriangleMesh decoded = std::get<TriangleMesh>(read_cnb(bytes, "linkrods.cnb").root.shapes.at(0).geometry);
  ASSERT_EQ(decoded.triangles.size(), mesh.triangles.size());
  ASSERT_EQ(decoded.positions.size(), mesh.positions.size());
  EXPECT_LE(largest_nearest_distance(mesh.positions, decoded.positions), report.point_bound * (1 + 1e-12));
  EXPECT_LE(largest_nearest_distance(decoded.positions, mesh.positions), report.point_bound * (1 + 1e-12));
  // Not all at the nearest grid point: some vertices moved farther than rounding moves them.
  const TriangleMesh on_grid = mesh_on_grid(mesh, report.point_step);
  EXPECT_GT(largest_nearest_distance(decoded.positions, on_grid.positions), 0.1 * report.point_step);
  EXPECT_EQ(count_boundary_edges(weld_exact(decoded)).boundary, count_boundary_edges(mesh).boundary);
}

// Meshes in different records that share vertices (two sheets of one wavy surface, meeting along a row,
// in two nodes, so not one group) keep those vertices where rounding puts them: the part does not crack.
TEST(CnbTraversalMesh, SharedVerticesStayWhereRoundingPutsThem) {
  const auto sheet = [](int i0, int i1) {
    TriangleMesh m;
    const int n = 24;
    for (int i = i0; i <= i1; ++i)
      for (int j = 0; j <= n; ++j)
        m.positions.emplace_back(0.37 * i + 0.05 * std::sin(1.3 * j), 0.41 * j, 0.8 * std::sin(0.31 * i) * std::cos(0.27 * j));
    const auto at = [&](int i, int j) { return (i - i0) * (n + 1) + j; };
    for (int i = i0; i < i1; ++i)
      for (int j = 0; j < n; ++j) {
        m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
        m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    return m;
  };
  Scene scene;
  for (auto [i0, i1] : {std::pair{0, 20}, std::pair{20, 40}}) {
    SceneNode node;
    node.shapes.push_back({"sheet", sheet(i0, i1), std::nullopt});
    scene.root.children.push_back(node);
  }
  CnbOptions options;
  options.max_deviation = 0.02;
  CnbWriteReport report;
  const Scene decoded = read_cnb(write_cnb(scene, options, &report), "sheets.cnb");
  EXPECT_GT(report.vertices_off_nearest, 0);
  const EdgeCounts original = count_boundary_edges(weld_exact(scene_triangles(scene))),
                   after = count_boundary_edges(weld_exact(scene_triangles(decoded)));
  EXPECT_EQ(original.boundary, 2 * 40 + 2 * 24);  // one sheet: the shared row is inside
  EXPECT_EQ(after.boundary, original.boundary);
}

// The certified mesh of a corpus part, coded by .cnb and by Draco with the same vertex budget (Draco at
// its coarsest bits that move no vertex farther than our grid may): .cnb is the smaller.
TEST(CnbTraversalMesh, SmallerThanDracoOnACorpusPartsCertifiedMesh) {
  const auto [mesh, options] = certified_part_mesh("step/dm1-id-214.stp", 1e-3, 0.5);
  const double d = options.max_deviation;
  CnbWriteReport report;
  const std::string ours = write_cnb(scene_of(mesh), options, &report);
  EXPECT_LE(report.deviation_bound(), d * (1 + 1e-12));
  const double budget = report.point_step * std::sqrt(3.0) / 2;
  int bits = 1;
  for (; bits <= 30; ++bits) {
    const auto moved = draco_quantised_positions(mesh, bits);
    double largest = 0;
    for (size_t i = 0; i < moved.size(); ++i) largest = std::max(largest, (moved[i] - mesh.positions[i]).norm());
    if (largest <= budget) break;
  }
  const std::string draco = encode_draco_mesh(mesh, bits, 0);
  std::cout << mesh.triangles.size() << " triangles: .cnb " << ours.size() << " bytes, Draco (" << bits << " bits) "
            << draco.size() << " bytes\n";
  EXPECT_LT(ours.size(), draco.size());
  Decoded decoded{ours, std::get<TriangleMesh>(read_cnb(ours, "part.cnb").root.shapes.at(0).geometry),
                  report.point_step};
  // Pieces coded as copies decode with their source's triangles, which may cut a flat face along another
  // diagonal: the same vertices, the same surface.
  EXPECT_GT(report.piece_copies, 0);
  const TriangleMesh on_grid = mesh_on_grid(mesh, report.point_step);
  ASSERT_EQ(decoded.mesh.triangles.size(), mesh.triangles.size());
  const auto sorted = [](std::vector<Eigen::Vector3d> points) {
    std::sort(points.begin(), points.end(), [](const auto& a, const auto& b) {
      return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
    });
    return points;
  };
  EXPECT_EQ(sorted(decoded.mesh.positions), sorted(on_grid.positions));
  EXPECT_NEAR(mesh_area(decoded.mesh), mesh_area(on_grid), 1e-9 * mesh_area(on_grid));
  const MeshDistance apart = mesh_distance(decoded.mesh, on_grid);
  EXPECT_LE(apart.a_to_b.max, 1e-9 * d);
  EXPECT_LE(apart.b_to_a.max, 1e-9 * d);
}

}  // namespace
}  // namespace cadnurbs
