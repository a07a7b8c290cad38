// cheapest_coding with the .cnb writer as its cost: what it meshes, that the file it picks is the
// smallest of the candidates, and that the decoded meshes are within D of the exact faces and closed.
#include "analysis/coding_choice/cheapest_coding.hpp"

#include <gtest/gtest.h>

#include <array>
#include <map>

#include "analysis/coding_choice/scene_bodies.hpp"
#include "analysis/compaction/compact_scene.hpp"
#include "analysis/measure/measure_deviation.hpp"
#include "analysis/mesh/count_boundary_edges.hpp"
#include "analysis/mesh/scene_triangles.hpp"
#include "analysis/mesh/weld_exact.hpp"
#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "core/bounding_box.hpp"
#include "formats/cnb/cnb_reader.hpp"
#include "formats/cnb/cnb_writer.hpp"
#include "formats/step/step_reader.hpp"

namespace cadnurbs {
namespace {

constexpr double kMeshShare = 0.4;

// One face of the cube [0, size]^3: the bilinear patch origin + u·a + v·b (a × b outward), trimmed by its
// domain's four sides, each on the cube edge between its two corners (edge number from the corner pair,
// so that neighbouring faces share it).
Shape cube_face(double size, const Eigen::Vector3i& origin, const Eigen::Vector3i& a, const Eigen::Vector3i& b) {
  const std::array<Eigen::Vector3i, 4> corners = {origin, origin + a, origin + a + b, origin + b};
  NurbsSurface surface;
  surface.u_count = surface.v_count = 2;
  surface.u_knots = surface.v_knots = {0, 0, 1, 1};
  surface.points = {size * corners[0].cast<double>(), size * corners[1].cast<double>(),
                    size * corners[3].cast<double>(), size * corners[2].cast<double>()};
  const std::array<Eigen::Vector2d, 4> domain = {Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0), Eigen::Vector2d(1, 1),
                                                 Eigen::Vector2d(0, 1)};
  auto corner_number = [](const Eigen::Vector3i& c) { return c.x() + 2 * c.y() + 4 * c.z(); };
  TrimLoop loop;
  for (int k = 0; k < 4; ++k) {
    loop.segments.push_back(Polyline2D{{domain[k], domain[(k + 1) % 4]}});
    const int from = corner_number(corners[k]), to = corner_number(corners[(k + 1) % 4]);
    loop.edges.push_back({8 * std::min(from, to) + std::max(from, to), from > to});
  }
  return {"", TrimmedSurface{surface, {loop}}, std::nullopt};
}

// The six faces of the cube, outward; -z, +z, -y, +y, -x, +x.
std::vector<Shape> cube_faces(double size) {
  const Eigen::Vector3i o(0, 0, 0), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  return {cube_face(size, o, y, x), cube_face(size, z, x, y), cube_face(size, o, x, z),
          cube_face(size, y, z, x), cube_face(size, o, z, y), cube_face(size, x, y, z)};
}

Scene scene_of(std::vector<SceneNode> nodes) {
  Scene scene;
  scene.root.name = "part";
  scene.root.children = std::move(nodes);
  return scene;
}

CodedBytes cnb_bytes(double d) {
  return [d](const Scene& scene, double mesh_deviation) {
    CnbOptions options;
    options.max_deviation = d;
    options.trim_share = kMeshShare;
    options.mesh_deviation = mesh_deviation;
    return write_cnb(scene, options).size();
  };
}

int shapes_holding_meshes(const SceneNode& node) {
  int meshes = 0;
  for (const auto& shape : node.shapes) meshes += std::holds_alternative<TriangleMesh>(shape.geometry);
  return meshes;
}

TEST(CheapestCoding, CubeAtCoarseDeviationIsMeshedAndSmallest) {
  const double size = 10, d = 0.5;
  const Scene cube = scene_of({{"cube", "", Eigen::Affine3d(Eigen::Translation3d(5, -2, 1)), {}, cube_faces(size)}});
  CodingChoiceReport report;
  const Scene chosen = cheapest_coding(cube, {d, kMeshShare}, cnb_bytes(d), &report);
  EXPECT_EQ(report.bodies, 1);
  EXPECT_EQ(report.bodies_meshed, 1);
  EXPECT_EQ(report.faces_meshed, 6);
  EXPECT_EQ(report.triangles, 12);  // a planar square is certified as two triangles at any D
  EXPECT_LE(report.certified_deviation, kMeshShare * d);
  ASSERT_EQ(shapes_holding_meshes(chosen.root.children[0]), 1);
  EXPECT_TRUE(std::get<TriangleMesh>(chosen.root.children[0].shapes[0].geometry).corner_normals.empty());
  const size_t chosen_bytes = cnb_bytes(d)(chosen, report.certified_deviation);
  EXPECT_EQ(chosen_bytes, report.bytes());
  EXPECT_LE(chosen_bytes, cnb_bytes(d)(cube, 0));
  EXPECT_LE(chosen_bytes, report.all_meshed_bytes);
  EXPECT_LT(chosen_bytes, report.as_is_bytes);
  std::cout << "cube: as is " << report.as_is_bytes << " bytes, meshed " << chosen_bytes << "\n";
}

TEST(CheapestCoding, DecodedCubeMeshIsWithinDeviationAndClosed) {
  const double d = 0.05;
  const Scene cube = scene_of({{"cube", "", Eigen::Affine3d(Eigen::Scaling(2.0)), {}, cube_faces(3)}});
  CodingChoiceReport report;
  const Scene chosen = cheapest_coding(cube, {d, kMeshShare}, cnb_bytes(d), &report);
  ASSERT_EQ(report.bodies_meshed, 1);
  CnbOptions options;
  options.max_deviation = d;
  options.trim_share = kMeshShare;
  options.mesh_deviation = report.certified_deviation;
  CnbWriteReport written;
  const Scene decoded = read_cnb(write_cnb(chosen, options, &written), "cube.cnb");
  EXPECT_LE(written.deviation_bound(), d * (1 + 1e-12));
  const TriangleMesh mesh = scene_triangles(decoded);
  ASSERT_EQ(mesh.triangles.size(), 12u);
  const DeviationMeasure measured = measure_deviation(mesh, cube);
  EXPECT_LE(measured.overall.max, d);
  EXPECT_GT(measured.surface_to_mesh.samples, 0);
  const EdgeCounts edges = count_boundary_edges(weld_exact(mesh));
  EXPECT_EQ(edges.boundary, 0);
  EXPECT_EQ(edges.non_manifold, 0);
}

// A closed analytic solid (cone, torus, cylinder, planes) at a coarse D: meshed, the decoded mesh within D
// of the exact faces both ways, and as closed as the exact part's own tessellation.
TEST(CheapestCoding, DecodedCurvedSolidIsWithinDeviationAndClosed) {
  const Scene part = read_step(std::string(CADNURBS_SHARED_DIR) + "/corpus/step/screw.step").scene;
  const double d = 2e-3 * scene_bounding_box(part).diagonal().norm();
  CodingChoiceReport report;
  const Scene chosen = cheapest_coding(part, {d, kMeshShare}, cnb_bytes(d), &report);
  ASSERT_EQ(report.bodies, 1);
  ASSERT_EQ(report.bodies_meshed, 1);
  EXPECT_EQ(report.faces_meshed, 10);
  EXPECT_GT(report.certified_deviation, 0);
  EXPECT_LE(report.certified_deviation, kMeshShare * d);
  CnbOptions options;
  options.max_deviation = d;
  options.trim_share = kMeshShare;
  options.mesh_deviation = report.certified_deviation;
  const Scene decoded = read_cnb(write_cnb(chosen, options), "screw.cnb");
  const TriangleMesh mesh = scene_triangles(decoded);
  const DeviationMeasure measured = measure_deviation(mesh, part);
  std::cout << "screw at D = " << d << ": " << mesh.triangles.size() << " triangles, measured "
            << measured.mesh_to_surface.max << " (mesh to surface), " << measured.surface_to_mesh.max
            << " (surface to mesh)\n";
  EXPECT_LE(measured.overall.max, d);
  EXPECT_GT(measured.overall.max, 0.05 * d);  // the meshes of the curved faces are not exact
  const EdgeCounts exact = count_boundary_edges(weld_exact(scene_triangles(tessellate_to_deviation(part, d))));
  ASSERT_EQ(exact.boundary, 0);
  const EdgeCounts edges = count_boundary_edges(weld_exact(mesh));
  EXPECT_EQ(edges.boundary, 0);
  EXPECT_EQ(edges.non_manifold, exact.non_manifold);
}

// A SolidWorks part with pockets and holes in its compact form (planar faces as exact polygons, which meet
// the cylinders at T-junctions), with the exact part given: every body of the exact part meshed is a candidate too, the
// smallest of the four is returned, and where that is the exact part's mesh the file reads back closed.
TEST(CheapestCoding, ExactPartMeshedIsACandidateAndReadsBackClosed) {
  const Scene part = read_step(std::string(CADNURBS_SHARED_DIR) + "/corpus/step/featuretype.STEP").scene;
  const double diagonal = scene_bounding_box(part).diagonal().norm();
  const Scene compact = compact_scene(part, 1e-6 * diagonal);
  ASSERT_GT(count_entities(compact).polygon_meshes, 0);
  const double d = 2e-3 * diagonal;
  CodingChoiceReport report;
  const Scene chosen = cheapest_coding(compact, {d, kMeshShare}, cnb_bytes(d), &report, &part);
  std::cout << "featuretype, compact form: as is " << report.as_is_bytes << ", per body " << report.per_body_bytes
            << ", all meshed " << report.all_meshed_bytes << ", exact part meshed " << report.exact_meshed_bytes
            << "\n";
  EXPECT_EQ(report.bytes(),
            std::min({report.as_is_bytes, report.per_body_bytes, report.all_meshed_bytes, report.exact_meshed_bytes}));
  ASSERT_EQ(report.chosen, CodingChoiceReport::Whole::exact_meshed);
  EXPECT_EQ(cnb_bytes(d)(chosen, report.certified_deviation), report.bytes());
  EXPECT_EQ(count_entities(chosen).polygon_meshes, 0);
  const TriangleMesh compact_meshed = scene_triangles(cheapest_coding(compact, {d, kMeshShare}, cnb_bytes(d)));
  CnbOptions options;
  options.max_deviation = d;
  options.trim_share = kMeshShare;
  options.mesh_deviation = report.certified_deviation;
  const TriangleMesh decoded = scene_triangles(read_cnb(write_cnb(chosen, options), "featuretype.cnb"));
  EXPECT_EQ(count_boundary_edges(weld_exact(decoded)).boundary, 0);
  EXPECT_LE(measure_deviation(decoded, part).overall.max, d);
  EXPECT_GT(count_boundary_edges(weld_exact(compact_meshed)).boundary, 0) << "the compact form's mesh is open";
}

// The same compact form, told that its bodies may meet along edges its loops do not name (its polygon sets
// name none): meshes of its own bodies would not join the NURBS beside them, so none is made, and the
// choice is between the NURBS as they are and the exact part's meshes.
TEST(CheapestCoding, BodiesThatMayMeetUnnamedAreNotMeshedOneByOne) {
  const Scene part = read_step(std::string(CADNURBS_SHARED_DIR) + "/corpus/step/featuretype.STEP").scene;
  const double diagonal = scene_bounding_box(part).diagonal().norm();
  const Scene compact = compact_scene(part, 1e-6 * diagonal);
  const double d = 2e-3 * diagonal;
  CodingChoiceReport named, unnamed;
  cheapest_coding(compact, {d, kMeshShare}, cnb_bytes(d), &named, &part);
  const Scene chosen = cheapest_coding(compact, {d, kMeshShare, false}, cnb_bytes(d), &unnamed, &part);
  EXPECT_NE(named.per_body_bytes, named.as_is_bytes) << "some bodies are cheaper meshed";
  EXPECT_EQ(unnamed.per_body_bytes, unnamed.as_is_bytes);
  EXPECT_EQ(unnamed.all_meshed_bytes, unnamed.as_is_bytes);
  EXPECT_EQ(unnamed.exact_meshed_bytes, named.exact_meshed_bytes);
  EXPECT_TRUE(unnamed.chosen == CodingChoiceReport::Whole::as_is ||
              unnamed.chosen == CodingChoiceReport::Whole::exact_meshed ||
              unnamed.chosen == CodingChoiceReport::Whole::merged_meshes);
  if (unnamed.bodies_meshed > 0) EXPECT_EQ(count_entities(chosen).surfaces, 0);
}

// Ten cubes of different sizes, each in a node of its own (nothing to share as copies): every body meshed,
// then placed in world coordinates and merged into one mesh per colour at the root, is one more candidate,
// smaller than ten meshes and the nodes that place them; decoded, it is within D of the cubes and closed.
TEST(CheapestCoding, MeshesMergedPerColourAreACandidate) {
  std::vector<SceneNode> nodes;
  for (int i = 0; i < 10; ++i) {
    std::vector<Shape> faces = cube_faces(1.0 + 0.37 * i);
    for (auto& shape : faces)
      for (auto& ref : std::get<TrimmedSurface>(shape.geometry).loops[0].edges) ref.edge += 100 * i;
    nodes.push_back({"cube " + std::to_string(i), "", Eigen::Affine3d(Eigen::Translation3d(6.0 * i, 0, 0)), {}, faces});
  }
  const Scene cubes = scene_of(nodes);
  const double d = 0.05;
  CodingChoiceReport report;
  const Scene chosen = cheapest_coding(cubes, {d, kMeshShare}, cnb_bytes(d), &report);
  std::cout << "ten cubes: as is " << report.as_is_bytes << ", all meshed " << report.all_meshed_bytes
            << ", merged per colour " << report.merged_meshes_bytes << "\n";
  EXPECT_EQ(report.bytes(),
            std::min({report.as_is_bytes, report.per_body_bytes, report.all_meshed_bytes, report.merged_meshes_bytes}));
  EXPECT_EQ(report.exact_meshed_bytes, 0u);
  ASSERT_EQ(report.chosen, CodingChoiceReport::Whole::merged_meshes);
  EXPECT_TRUE(chosen.root.children.empty());
  EXPECT_EQ(report.bodies_meshed, 10);
  CnbOptions options;
  options.max_deviation = d;
  options.trim_share = kMeshShare;
  options.mesh_deviation = report.certified_deviation;
  const TriangleMesh decoded = scene_triangles(read_cnb(write_cnb(chosen, options), "cubes.cnb"));
  EXPECT_EQ(decoded.triangles.size(), 120u);
  EXPECT_LE(measure_deviation(decoded, cubes).overall.max, d);
  EXPECT_EQ(count_boundary_edges(weld_exact(decoded)).boundary, 0);
}

// Node "a" holds three faces of a cube, node "b" the other three (sharing its edges), node "c" a cube of
// its own. Meshing pays in "a" and "c" only; "a" and "b" are one body, so they go together.
TEST(CheapestCoding, NodesSharingAnEdgeAreMeshedTogetherOrNotAtAll) {
  std::vector<Shape> faces = cube_faces(4);
  const std::vector<Shape> first(faces.begin(), faces.begin() + 3), second(faces.begin() + 3, faces.end());
  std::vector<Shape> other = cube_faces(4);
  for (auto& shape : other)
    for (auto& ref : std::get<TrimmedSurface>(shape.geometry).loops[0].edges) ref.edge += 1000;
  const Scene scene = scene_of({{"a", "", Eigen::Affine3d::Identity(), {}, first},
                                {"b", "", Eigen::Affine3d::Identity(), {}, second},
                                {"c", "", Eigen::Affine3d(Eigen::Translation3d(10, 0, 0)), {}, other}});
  const SceneBodies bodies = scene_bodies(scene);
  ASSERT_EQ(bodies.bodies.size(), 2u);
  EXPECT_EQ(bodies.bodies[0], (std::vector<int>{1, 2}));
  EXPECT_EQ(bodies.bodies[1], (std::vector<int>{3}));
  // A cost that rewards a mesh in "a" and "c" and punishes one in "b" more than "a" gains.
  const std::map<std::string, std::array<size_t, 2>> cost = {{"a", {100, 10}}, {"b", {100, 250}}, {"c", {100, 10}}};
  const auto coded_bytes = [&](const Scene& s, double) {
    size_t bytes = 0;
    for (const auto& node : s.root.children) bytes += cost.at(node.name)[shapes_holding_meshes(node) > 0];
    return bytes;
  };
  CodingChoiceReport report;
  const Scene chosen = cheapest_coding(scene, {0.1, kMeshShare}, coded_bytes, &report);
  EXPECT_EQ(shapes_holding_meshes(chosen.root.children[0]), 0);
  EXPECT_EQ(shapes_holding_meshes(chosen.root.children[1]), 0);
  EXPECT_EQ(shapes_holding_meshes(chosen.root.children[2]), 1);
  EXPECT_EQ(report.chosen, CodingChoiceReport::Whole::per_body);
  EXPECT_EQ(report.bodies_meshed, 1);
  EXPECT_EQ(report.as_is_bytes, 300u);
  EXPECT_EQ(report.per_body_bytes, 210u);  // a, b as they are; c meshed
  EXPECT_EQ(report.all_meshed_bytes, 270u);
}

TEST(CheapestCoding, FreeformPartAtFineDeviationStaysNurbs) {
  const Scene part = read_step(std::string(CADNURBS_SOURCE_DIR) + "/samples/capping-moulded.step").scene;
  const double d = 1e-3 * scene_bounding_box(part).diagonal().norm();  // fine: 0.1 % of the part's size
  CodingChoiceReport report;
  const Scene chosen = cheapest_coding(part, {d, kMeshShare}, cnb_bytes(d), &report);
  EXPECT_GT(report.bodies, 0);
  EXPECT_EQ(report.bodies_meshed, 0);
  EXPECT_EQ(report.chosen, CodingChoiceReport::Whole::as_is);
  EXPECT_GT(report.all_meshed_bytes, report.as_is_bytes);
  EXPECT_EQ(count_entities(chosen).meshes, count_entities(part).meshes);
  std::cout << "capping-moulded at " << d << ": NURBS " << report.as_is_bytes << " bytes, meshed "
            << report.all_meshed_bytes << "\n";
}

}  // namespace
}  // namespace cadnurbs
