// tessellate_to_deviation on analytic shapes: the deviation is checked against the exact distance
// functions (independent of our NURBS code) and against measure_deviation; triangle counts per D
// are printed.
#include <gtest/gtest.h>

#include <cstdio>
#include <functional>

#include "analysis/mesh/count_boundary_edges.hpp"
#include "analysis/measure/measure_deviation.hpp"
#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "analysis/mesh/weld_exact.hpp"
#include "analysis_shapes.hpp"
#include "core/geometry_error.hpp"

namespace cadnurbs {
namespace {

using Distance = std::function<double(const Eigen::Vector3d&)>;

// Largest exact distance of the mesh: every triangle sampled on a lattice of 6 divisions.
double max_exact_distance(const TriangleMesh& mesh, const Distance& distance) {
  double worst = 0;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.positions[t[0]];
    const Eigen::Vector3d& b = mesh.positions[t[1]];
    const Eigen::Vector3d& c = mesh.positions[t[2]];
    constexpr int n = 6;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) worst = std::max(worst, distance((a * (n - i - j) + b * i + c * j) / n));
  }
  return worst;
}

struct Case {
  const char* name;
  TrimmedSurface surface;
  Distance distance;  // empty: no analytic distance (planar: z)
};

std::vector<Case> cases() {
  return {
      {"quarter cylinder r20 h40", test::quarter_cylinder(20, 40),
       [](const Eigen::Vector3d& p) { return test::distance_to_cylinder(p, 20); }},
      {"sphere r50", test::sphere(50), [](const Eigen::Vector3d& p) { return test::distance_to_sphere(p, 50); }},
      {"torus patch R40 r10", test::torus_patch(40, 10),
       [](const Eigen::Vector3d& p) { return test::distance_to_torus(p, 40, 10); }},
      {"annulus in a 100 mm square", test::trimmed_square(100, 0.4, 0.15),
       [](const Eigen::Vector3d& p) { return std::abs(p.z()); }},
  };
}

TEST(TessellateToDeviation, AnalyticShapesStayWithinDeviation) {
  for (const Case& c : cases()) {
    long previous = -1;
    for (double d : {0.01, 0.1, 1.0}) {
      TessellationReport report;
      const TriangleMesh mesh = tessellate_to_deviation(c.surface, d, &report);
      ASSERT_NO_THROW(validate(mesh, c.name));
      const double exact = max_exact_distance(mesh, c.distance);
      const DeviationMeasure m = measure_deviation(mesh, c.surface);
      std::printf("  %-28s D=%-5g triangles %7zu  certified %.4g  exact(mesh->surface) %.4g  measured "
                  "mesh->surface %.4g surface->mesh %.4g\n",
                  c.name, d, mesh.triangles.size(), report.certified_deviation, exact, m.mesh_to_surface.max,
                  m.surface_to_mesh.max);
      EXPECT_EQ(report.uncertified_triangles, 0) << c.name << " D=" << d;
      EXPECT_LE(report.certified_deviation, d) << c.name;
      EXPECT_LE(exact, d * (1 + 1e-9)) << c.name << " D=" << d;
      EXPECT_LE(m.overall.max, d * (1 + 1e-9)) << c.name << " D=" << d;
      if (previous >= 0) {
        EXPECT_LT(static_cast<long>(mesh.triangles.size()), previous) << c.name << " D=" << d;
      }
      previous = static_cast<long>(mesh.triangles.size());
      ASSERT_EQ(mesh.corner_normals.size(), 3 * mesh.triangles.size());
    }
  }
}

TEST(TessellateToDeviation, NormalsPointOutOfTheSphere) {
  const TriangleMesh mesh = tessellate_to_deviation(test::sphere(50), 0.1);
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Eigen::Vector3d& a = mesh.positions[tri[0]];
    const Eigen::Vector3d n = (mesh.positions[tri[1]] - a).cross(mesh.positions[tri[2]] - a);
    ASSERT_GT(n.dot(a), 0) << "triangle " << t << " faces inward";
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d& p = mesh.positions[tri[k]];
      ASSERT_GT(mesh.corner_normals[3 * t + k].dot(p.normalized()), 0.999) << "corner normal " << t;
    }
  }
}

TEST(TessellateToDeviation, UntrimmedSphereIsClosedWithoutSlivers) {
  // Seam and poles of an untrimmed closed surface share their vertices.
  const TriangleMesh mesh = tessellate_to_deviation(test::sphere(50), 0.1);
  const EdgeCounts e = count_boundary_edges(mesh);
  EXPECT_EQ(e.boundary, 0);
  EXPECT_EQ(e.non_manifold, 0);
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.positions[t[0]];
    EXPECT_GT((mesh.positions[t[1]] - a).cross(mesh.positions[t[2]] - a).norm(), 1e-9) << "a sliver";
  }
  // Euler characteristic of a sphere.
  EXPECT_EQ(static_cast<long>(mesh.positions.size()) - static_cast<long>(mesh.triangles.size()) * 3 / 2 +
                static_cast<long>(mesh.triangles.size()),
            2);
}

TEST(TessellateToDeviation, RefusesBadInput) {
  EXPECT_THROW(tessellate_to_deviation(test::sphere(1), 0.0), GeometryError);
  EXPECT_THROW(tessellate_to_deviation(test::sphere(1), -1.0), GeometryError);
  // A loop that does not close.
  TrimmedSurface open = test::trimmed_square(10, 0.4, 0.1);
  open.loops[0].segments.emplace_back(Polyline2D{{{0.1, 0.1}, {0.2, 0.2}}});
  EXPECT_THROW(tessellate_to_deviation(open, 0.1), GeometryError);
}

TEST(TessellateToDeviation, BadFaceInSceneNamesTheShape) {
  Scene scene;
  scene.root.name = "part";
  scene.root.shapes.push_back({"good", test::quarter_cylinder(10, 10), std::nullopt});
  TrimmedSurface bad = test::trimmed_square(10, 0.4, 0.1);
  // A hole far outside the domain (the reader's repair would have refused it).
  bad.loops[1].segments = {Polyline2D{{{3, 3}, {3.5, 3}, {3.5, 3.5}, {3, 3}}}};
  scene.root.shapes.push_back({"lid", bad, std::nullopt});
  try {
    tessellate_to_deviation(scene, 0.1);
    FAIL() << "no GeometryError";
  } catch (const GeometryError& e) {
    EXPECT_NE(std::string(e.what()).find("part/lid"), std::string::npos) << e.what();
  }
}

// Loops that bound no area as sampled at D (here: two points and back, a hole and a whole face's outer
// loop; in real files slivers that the reader's finer samples kept) trim nothing and mesh to nothing; the
// rest of the scene meshes. Such a face used to fail the whole scene with "trimming loop 0 bounds no
// area" where its .x3dv output was written.
TEST(TessellateToDeviation, LoopsThinnerThanTheDeviationMeshToNothing) {
  Scene scene;
  scene.root.shapes.push_back({"good", test::quarter_cylinder(10, 10), std::nullopt});
  TrimmedSurface holed = test::trimmed_square(10, 0.4, 0.1);
  holed.loops[1].segments = {Polyline2D{{{0.5, 0.5}, {0.6, 0.5}}}, Polyline2D{{{0.6, 0.5}, {0.5, 0.5}}}};
  scene.root.shapes.push_back({"holed", holed, std::nullopt});
  TrimmedSurface sliver = test::trimmed_square(10, 0.4, 0.1);
  sliver.loops = {TrimLoop{{Polyline2D{{{0.2, 0.5}, {0.8, 0.5}}}, Polyline2D{{{0.8, 0.5}, {0.2, 0.5}}}}, {}}};
  scene.root.shapes.push_back({"sliver", sliver, std::nullopt});
  TessellationReport report;
  const Scene meshed = tessellate_to_deviation(scene, 0.01, &report);
  EXPECT_EQ(report.loops_without_area, 2);
  EXPECT_EQ(report.uncertified_triangles, 0);
  EXPECT_GT(std::get<TriangleMesh>(meshed.root.shapes[0].geometry).triangles.size(), 0u);
  // The holed face is the whole annulus: its hole of no area trims nothing.
  const TriangleMesh& annulus = std::get<TriangleMesh>(meshed.root.shapes[1].geometry);
  EXPECT_GT(annulus.triangles.size(), 0u);
  const double pi = 3.14159265358979323846, exact = pi * 16;  // a disc of radius 0.4 x 10
  EXPECT_NEAR(mesh_area(annulus), exact, 0.01 * 2 * pi * 4);
  EXPECT_EQ(std::get<TriangleMesh>(meshed.root.shapes[2].geometry).triangles.size(), 0u);
}

// A side made of edges shorter than D/2 that no other face names (a sewn file's open rim, such as the
// impeller's blades): each is a possible gap closure, one vertex, but ten in a row span 5 D and must not
// all become one vertex. Before the run rule they did: the square's bottom side pulled to one point left
// its triangles uncertified (the impeller's blade: 494 of 19,611 at 1e-2 of its diagonal, against 0 of 66).
TEST(TessellateToDeviation, RunsOfShortOpenEdgesKeepTheirLength) {
  TrimmedSurface square = test::trimmed_square(10, 0.4, 0.1);
  TrimLoop loop;
  for (int k = 0; k < 10; ++k) loop.segments.push_back(Polyline2D{{{0.1 * k, 0.0}, {0.1 * (k + 1), 0.0}}});
  loop.segments.push_back(Polyline2D{{{1, 0}, {1, 1}, {0, 1}, {0, 0}}});
  loop.edges.assign(loop.segments.size(), TrimEdgeRef{});  // -1: shared with nothing
  square.loops = {loop};
  const double d = 2.0;  // each bottom edge 1 long: below D/2, the ten 5 D
  TessellationReport report;
  const TriangleMesh mesh = tessellate_to_deviation(square, d, &report);
  EXPECT_EQ(report.uncertified_triangles, 0);
  EXPECT_LE(report.certified_deviation, d);
  EXPECT_NEAR(mesh_area(mesh), 100.0, 1e-9);
}

TEST(TessellateToDeviation, SceneKeepsNamesColoursAndMeshes) {
  Scene scene;
  scene.root.name = "root";
  scene.root.colour = Colour{0.1, 0.2, 0.3};
  SceneNode child;
  child.name = "child";
  child.transform.translate(Eigen::Vector3d(1, 2, 3));
  child.shapes.push_back({"cyl", test::quarter_cylinder(10, 10), Colour{1, 0, 0}});
  TriangleMesh tri;
  tri.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  tri.triangles = {{0, 1, 2}};
  child.shapes.push_back({"mesh", tri, std::nullopt});
  scene.root.children.push_back(child);
  const Scene out = tessellate_to_deviation(scene, 0.1);
  ASSERT_EQ(out.root.children.size(), 1u);
  const auto& c = out.root.children[0];
  EXPECT_EQ(c.name, "child");
  EXPECT_TRUE(c.transform.isApprox(scene.root.children[0].transform));
  ASSERT_EQ(c.shapes.size(), 2u);
  EXPECT_EQ(c.shapes[0].name, "cyl");
  EXPECT_EQ(c.shapes[0].colour, (Colour{1, 0, 0}));
  EXPECT_TRUE(std::holds_alternative<TriangleMesh>(c.shapes[0].geometry));
  EXPECT_EQ(std::get<TriangleMesh>(c.shapes[1].geometry).triangles.size(), 1u);
  EXPECT_EQ(out.root.colour, scene.root.colour);
}

}  // namespace
}  // namespace cadnurbs
