// Shared edges: faces that name the same model edge get bit-identical vertices there, so a closed
// solid tessellates to a closed mesh (zero boundary and non-manifold edges after weld_exact).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "analysis/mesh/count_boundary_edges.hpp"
#include "analysis/measure/measure_deviation.hpp"
#include "analysis/mesh/scene_triangles.hpp"
#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "analysis/mesh/weld_exact.hpp"
#include "analysis/eval/sample_trim_segment.hpp"
#include "core/geometry_error.hpp"
#include "analysis_shapes.hpp"
#include "samples/capping.hpp"
#include "samples/capping_edges.hpp"
#include "samples/capping_shapes.hpp"

namespace cadnurbs {
namespace {


// The capping with edge ids (samples/capping_edges.hpp).
Scene capping_with_edges(const std::string& name) {
  Scene scene = capping_nurbs(bundled_capping(name));
  share_capping_edges(scene);
  return scene;
}

TriangleMesh node_mesh(const Scene& tessellated) {
  TriangleMesh all;
  for (const auto& shape : tessellated.root.shapes) append(all, std::get<TriangleMesh>(shape.geometry));
  return all;
}

TEST(Watertight, SphereWithSeamAndPolesIsClosed) {
  Scene scene;
  scene.root.shapes.push_back({"ball", test::sphere_with_edges(50, 7), std::nullopt});
  for (double d : {1.0, 0.1}) {
    const TriangleMesh mesh = weld_exact(node_mesh(tessellate_to_deviation(scene, d)));
    const EdgeCounts e = count_boundary_edges(mesh);
    EXPECT_EQ(e.boundary, 0) << "D=" << d;
    EXPECT_EQ(e.non_manifold, 0) << "D=" << d;
  }
}

// The capping `name` meshed within each of `deviations` (ascending): closed, certified, every body vertex
// and triangle centre within D of the exact sweep (known in closed form), measured within D both ways,
// and fewer triangles at each larger D.
void expect_capping_closes_up(const std::string& name, const std::vector<double>& deviations) {
  const Scene scene = capping_with_edges(name);
  const CappingDefinition def = bundled_capping(name);
  long previous = -1;
  for (double d : deviations) {
    TessellationReport report;
    const Scene out = tessellate_to_deviation(scene, d, &report);
    ASSERT_EQ(out.root.shapes.size(), 3u);
    EXPECT_EQ(out.root.shapes[0].name, "body");
    const TriangleMesh all = node_mesh(out);
    const TriangleMesh welded = weld_exact(all);
    const EdgeCounts e = count_boundary_edges(welded);
    EXPECT_EQ(e.boundary, 0) << name << " D=" << d;
    EXPECT_EQ(e.non_manifold, 0) << name << " D=" << d;
    EXPECT_EQ(report.uncertified_triangles, 0) << name << " D=" << d;
    EXPECT_EQ(report.unshared_edge_uses, 0) << name << " D=" << d;
    const TriangleMesh& body = std::get<TriangleMesh>(out.root.shapes[0].geometry);
    double exact = 0;
    for (const auto& t : body.triangles) {
      const Eigen::Vector3d c = (body.positions[t[0]] + body.positions[t[1]] + body.positions[t[2]]) / 3.0;
      exact = std::max(exact, distance_to_swept_surface(def, c));
    }
    const DeviationMeasure m = measure_deviation(all, scene);
    std::printf("  %-12s D=%-5g triangles %7zu (body %zu)  certified %.4g  body centres exact %.4g  measured "
                "mesh->surface %.4g surface->mesh %.4g\n",
                name.c_str(), d, all.triangles.size(), body.triangles.size(), report.certified_deviation, exact,
                m.mesh_to_surface.max, m.surface_to_mesh.max);
    EXPECT_LE(exact, d * (1 + 1e-9)) << name;
    EXPECT_LE(m.overall.max, d * (1 + 1e-9)) << name << " D=" << d;
    if (previous >= 0) EXPECT_LT(static_cast<long>(all.triangles.size()), previous) << name;
    previous = static_cast<long>(all.triangles.size());
  }
}

TEST(Watertight, CappingBodyAndLidsCloseUp) {
  for (const std::string name : {"capping-90", "capping-end"}) expect_capping_closes_up(name, {0.1, 1.0});
}

// The same at D = 0.01 (long tier: its measurement alone takes about a minute).
TEST(Watertight, CappingBodyAndLidsCloseUpAtAHundredthOfAMillimetre) {
  expect_capping_closes_up("capping-90", {0.01, 0.1});
}

// A square face F whose hole, a triangle, touches its outer loop at (1,0), and the triangle's own face G
// on a plane parametrised at an angle, so that G evaluates that vertex a few bits away from (1,0,0). The
// loops reach the vertex from two vertex classes (F's outer edges, the triangle's edges): they must
// still be one mesh node, or F's hole chords and G's differ there and the mesh opens (the lens of
// LED_D3.0mm_Horizontal, where a cylinder is tangent to a cut plane). Welded, F and G are one square:
// its only boundary is the square's perimeter, 8.
TEST(Watertight, InnerLoopTouchingOuterLoopSharesTheVertex) {
  auto line = [](Eigen::Vector2d a, Eigen::Vector2d b) {
    NurbsCurve c;
    c.dimension = 2;
    c.order = 2;
    c.points = {Eigen::Vector3d(a.x(), a.y(), 0), Eigen::Vector3d(b.x(), b.y(), 0)};
    c.knots = {0, 0, 1, 1};
    return c;
  };
  auto loop = [&](const std::vector<Eigen::Vector2d>& corners, const std::vector<TrimEdgeRef>& edges) {
    TrimLoop l;
    for (size_t i = 0; i < corners.size(); ++i) l.segments.emplace_back(line(corners[i], corners[(i + 1) % corners.size()]));
    l.edges = edges;
    return l;
  };
  const double angle = 0.3, c = std::cos(angle), s = std::sin(angle);
  const Eigen::Vector3d a(c, s, 0), b(-s, c, 0);  // G's u and v directions
  auto uv_on_g = [&](double x, double y) { return Eigen::Vector2d(x * c + y * s, -x * s + y * c); };
  TrimmedSurface g;
  g.surface.u_count = g.surface.v_count = 2;
  g.surface.u_knots = g.surface.v_knots = {-3, -3, 3, 3};
  g.surface.points = {-3 * a - 3 * b, 3 * a - 3 * b, -3 * a + 3 * b, 3 * a + 3 * b};
  g.loops.push_back(loop({uv_on_g(1, 0), uv_on_g(1.5, 1), uv_on_g(0.5, 1)}, {{7, true}, {6, true}, {5, true}}));
  ASSERT_NE((surface_point(g.surface, uv_on_g(1, 0).x(), uv_on_g(1, 0).y()) - Eigen::Vector3d(1, 0, 0)).norm(), 0.0)
      << "G must evaluate the vertex off (1,0,0) for this test to mean anything";
  TrimmedSurface f;
  f.surface.u_count = f.surface.v_count = 2;
  f.surface.u_knots = f.surface.v_knots = {0, 0, 2, 2};
  f.surface.points = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {2, 2, 0}};
  f.loops.push_back(loop({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}, {{0, false}, {1, false}, {2, false}, {3, false}, {4, false}}));
  f.loops.push_back(loop({{1, 0}, {0.5, 1}, {1.5, 1}}, {{5, false}, {6, false}, {7, false}}));
  Scene scene;
  scene.root.shapes.push_back({"G", g, std::nullopt});  // first: G places the triangle's vertex
  scene.root.shapes.push_back({"F", f, std::nullopt});
  for (double d : {0.1, 0.01}) {
    TessellationReport report;
    const TriangleMesh mesh = weld_exact(node_mesh(tessellate_to_deviation(scene, d, &report)));
    const EdgeCounts e = count_boundary_edges(mesh);
    EXPECT_NEAR(e.boundary_length, 8.0, 1e-12) << "D=" << d;
    EXPECT_EQ(e.non_manifold, 0) << "D=" << d;
    EXPECT_EQ(report.unshared_edge_uses, 0) << "D=" << d;
  }
}

TEST(Watertight, WeldExactMergesOnlyIdenticalPositions) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 1e-300}};
  m.triangles = {{0, 1, 2}, {3, 4, 5}};
  const TriangleMesh w = weld_exact(m);
  EXPECT_EQ(w.positions.size(), 5u);  // (1,0,0) merged; (0,1,1e-300) is not (0,1,0)
  EXPECT_EQ(count_boundary_edges(w).boundary, 6);
  TriangleMesh fan;
  fan.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  fan.triangles = {{0, 1, 2}, {0, 2, 1}, {0, 1, 3}};
  const EdgeCounts e = count_boundary_edges(fan);
  EXPECT_EQ(e.non_manifold, 1);  // edge 0-1 has three triangles
}

// unshared_edge_uses gives tessellate_to_deviation's count from its edge sampling alone: 0 for the capping,
// and the same count once a lid is moved 10 D off the body's edges.
TEST(Watertight, UnsharedEdgeUsesCountsAsTheWholeTessellationDoes) {
  const double d = 0.05;
  Scene scene = capping_with_edges("capping-90");
  TessellationReport whole;
  tessellate_to_deviation(scene, d, &whole);
  EXPECT_EQ(whole.unshared_edge_uses, 0);
  EXPECT_EQ(unshared_edge_uses(scene, d), 0);
  for (Eigen::Vector3d& p : std::get<TrimmedSurface>(scene.root.shapes[1].geometry).surface.points) p.x() += 10 * d;
  TessellationReport moved;
  tessellate_to_deviation(scene, d, &moved);
  EXPECT_GT(moved.unshared_edge_uses, 0);
  EXPECT_EQ(unshared_edge_uses(scene, d), moved.unshared_edge_uses);
  EXPECT_THROW(unshared_edge_uses(scene, 0.0), GeometryError);
}

}  // namespace
}  // namespace cadnurbs
