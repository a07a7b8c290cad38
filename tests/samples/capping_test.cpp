#include <gtest/gtest.h>

#include <map>
#include <random>

#include "analysis/tessellation/tessellate_uniform.hpp"
#include "core/bounding_box.hpp"
#include "samples/capping_shapes.hpp"

using namespace cadnurbs;

namespace {

const TrimmedSurface& shape_named(const Scene& scene, const std::string& name) {
  for (const auto& s : scene.root.shapes)
    if (s.name == name) return std::get<TrimmedSurface>(s.geometry);
  throw std::runtime_error("no shape " + name);
}

// Signed volume enclosed by triangles (divergence theorem); positive when normals point outward.
double signed_volume(const TriangleMesh& m) {
  double v = 0;
  for (const auto& t : m.triangles) v += m.positions[t[0]].dot(m.positions[t[1]].cross(m.positions[t[2]])) / 6.0;
  return v;
}

class Capping : public ::testing::TestWithParam<std::string> {};

}  // namespace

TEST_P(Capping, SweptSurfaceLiesOnTheExactSweep) {
  const CappingDefinition def = bundled_capping(GetParam());
  const Scene scene = capping_nurbs(def);
  const double size = scene_bounding_box(scene).diagonal().norm();
  const NurbsSurface& body = shape_named(scene, "body").surface;
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(body.u_start(), body.u_end()), v(body.v_start(), body.v_end());
  double worst = 0;
  for (int i = 0; i < 200; ++i) worst = std::max(worst, distance_to_swept_surface(def, surface_point(body, u(rng), v(rng))));
  EXPECT_LE(worst, 1e-9 * size) << "model size " << size;
}

TEST_P(Capping, ExactSweepCheckRejectsAMovedPoint) {
  // The check above can fail: a point 0.01 mm off the surface is measured as such.
  const CappingDefinition def = bundled_capping(GetParam());
  const Scene scene = capping_nurbs(def);
  const NurbsSurface& body = shape_named(scene, "body").surface;
  const double um = 0.5 * (body.u_start() + body.u_end()) + 0.1, vm = 0.5 * (body.v_start() + body.v_end()) + 0.1;
  const Eigen::Vector3d p = surface_point(body, um, vm) + 0.01 * surface_normal(body, um, vm);
  EXPECT_NEAR(distance_to_swept_surface(def, p), 0.01, 1e-9);
}

TEST_P(Capping, LidLoopsCloseAndRunCounterClockwise) {
  const Scene scene = capping_nurbs(bundled_capping(GetParam()));
  for (const char* name : {"lid-start", "lid-end"}) {
    const TrimmedSurface& lid = shape_named(scene, name);
    ASSERT_EQ(lid.loops.size(), 1u) << name;
    EXPECT_LE(loop_closure_gap(lid.loops[0]), 1e-12) << name;
    EXPECT_GT(loop_signed_area(lid.loops[0]), 0.0) << name;
    // The loop stays inside the lid's (u, v) domain.
    for (const auto& p : loop_polygon(lid.loops[0]))
      EXPECT_TRUE(p.x() > 0 && p.x() < 1 && p.y() > 0 && p.y() < 1) << name;
  }
}

TEST_P(Capping, LidsMeetTheBodyEnds) {
  // The lid's trimming loop, mapped through the lid, traces the body's end cross-section.
  const Scene scene = capping_nurbs(bundled_capping(GetParam()));
  const NurbsSurface& body = shape_named(scene, "body").surface;
  for (const auto& [name, v] : {std::pair{"lid-start", body.v_start()}, {"lid-end", body.v_end()}}) {
    const TrimmedSurface& lid = shape_named(scene, name);
    const NurbsCurve& loop = std::get<NurbsCurve>(lid.loops[0].segments[0]);
    for (int i = 0; i <= 200; ++i) {
      const double t = loop.domain_start() + (loop.domain_end() - loop.domain_start()) * i / 200.0;
      const Eigen::Vector3d uv = curve_point(loop, t);
      const Eigen::Vector3d on_lid = surface_point(lid.surface, uv.x(), uv.y());
      // Nearest point of the body's end curve, sampled densely.
      double best = 1e9;
      for (int k = 0; k <= 4000; ++k)
        best = std::min(best, (surface_point(body, body.u_start() + (body.u_end() - body.u_start()) * k / 4000.0, v) - on_lid).norm());
      EXPECT_LT(best, 0.05) << name;
    }
  }
}

TEST_P(Capping, NurbsAndMeshEncloseTheSameVolumeWithOutwardNormals) {
  const CappingDefinition def = bundled_capping(GetParam());
  const Scene scene = capping_nurbs(def);
  TriangleMesh from_nurbs;
  for (const auto& s : scene.root.shapes) append(from_nurbs, tessellate_uniform(std::get<TrimmedSurface>(s.geometry), 16));
  const TriangleMesh mesh = capping_mesh(def, 0.01);
  const double v_nurbs = signed_volume(from_nurbs), v_mesh = signed_volume(mesh);
  EXPECT_GT(v_nurbs, 0.0);
  EXPECT_GT(v_mesh, 0.0);
  EXPECT_NEAR(v_mesh / v_nurbs, 1.0, 2e-3);
}

TEST_P(Capping, MeshIsClosed) {
  const TriangleMesh mesh = capping_mesh(bundled_capping(GetParam()), 0.5);
  std::map<std::pair<int, int>, int> edges;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++edges[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
  int open = 0, nonmanifold = 0;
  for (const auto& [e, n] : edges) open += n == 1, nonmanifold += n > 2;
  EXPECT_EQ(open, 0);
  EXPECT_EQ(nonmanifold, 0);
}

// Chords keep the bound along each arc; where path and profile arcs cross the errors add (2 d).
TEST_P(Capping, MeshStaysWithinTwiceTheChordDeviationOfTheSurface) {
  const CappingDefinition def = bundled_capping(GetParam());
  for (double d : {1.0, 0.1}) {
    const TriangleMesh mesh = capping_mesh(def, d, false);
    double worst = 0;
    for (const auto& t : mesh.triangles) {
      const Eigen::Vector3d &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
      for (const Eigen::Vector3d& p : {Eigen::Vector3d((a + b) / 2), Eigen::Vector3d((b + c) / 2),
                                       Eigen::Vector3d((c + a) / 2), Eigen::Vector3d((a + b + c) / 3)}) {
        worst = std::max(worst, distance_to_swept_surface(def, p));
      }
    }
    EXPECT_LE(worst, 2 * d) << d;
    EXPECT_GT(worst, 0.25 * d) << d;
  }
}

TEST_P(Capping, CoarserChordDeviationGivesFewerTriangles) {
  const CappingDefinition def = bundled_capping(GetParam());
  EXPECT_LT(capping_mesh(def, 1.0).triangles.size(), capping_mesh(def, 0.1).triangles.size());
}

INSTANTIATE_TEST_SUITE_P(Bundled, Capping, ::testing::ValuesIn(capping_shape_names()),
                         [](const auto& info) {
                           std::string n = info.param;
                           for (auto& c : n) if (c == '-') c = '_';
                           return n;
                         });

TEST(CappingCounts, NinetyDegreeCappingHasTheExpectedNet) {
  // Profile: 2 x 5 segments -> 21 points; path: line, arc, line -> 7 points.
  const Scene scene = capping_nurbs(bundled_capping("capping-90"));
  const auto& body = shape_named(scene, "body").surface;
  EXPECT_EQ(body.u_count, 21);
  EXPECT_EQ(body.v_count, 7);
  const auto counts = count_entities(scene);
  EXPECT_EQ(counts.control_points, 21 * 7 + 4 + 4);
}

// The thesis's 90-degree capping (seed 001, 6.1): 591 control points, 104 knots, 4 x 591 + 104 = 2,468
// floats. Counted here from the nets themselves, the way the thesis counts (x, y, z, w per point).
TEST(CappingCounts, MouldedCappingIsAsDetailedAsTheThesisCapping) {
  const auto thesis_floats = [](const Scene& scene, long& points, long& knots) {
    points = knots = 0;
    for (const auto& s : scene.root.shapes) {
      const NurbsSurface& n = std::get<TrimmedSurface>(s.geometry).surface;
      points += static_cast<long>(n.u_count) * n.v_count;
      knots += static_cast<long>(n.u_knots.size() + n.v_knots.size());
    }
    return 4 * points + knots;
  };
  const CappingDefinition moulded = bundled_capping("capping-moulded");
  int arcs = 0;
  for (const auto& s : moulded.half_profile.segments) arcs += s.is_arc;
  EXPECT_EQ(moulded.half_profile.segments.size(), 17u);
  EXPECT_EQ(arcs, 9);
  // Half profile: 8 lines, 8 arcs of at most 90 degrees and the 180-degree bead groove in two
  // pieces = 18 pieces; the whole profile 36 pieces -> 1 + 2 x 36 = 73 points; the path 7.
  const Scene scene = capping_nurbs(moulded);
  const NurbsSurface& body = shape_named(scene, "body").surface;
  EXPECT_EQ(body.u_count, 73);
  EXPECT_EQ(body.v_count, 7);
  long points = 0, knots = 0, points_90 = 0, knots_90 = 0;
  const long floats = thesis_floats(scene, points, knots);
  const long floats_90 = thesis_floats(capping_nurbs(bundled_capping("capping-90")), points_90, knots_90);
  // 73 x 7 + two 2 x 2 lids = 519 points; knots (73 + 3) + (7 + 3) + 2 x 8 = 102.
  EXPECT_EQ(points, 519);
  EXPECT_EQ(knots, 102);
  EXPECT_EQ(floats, 2178);
  EXPECT_EQ(floats_90, 670);
  EXPECT_GE(floats, 3 * floats_90);
  // count_entities (what demo and report print) counts the same.
  const SceneCounts c = count_entities(scene);
  EXPECT_EQ(c.control_points, points);
  EXPECT_EQ(c.knots, knots);
}

TEST(CappingErrors, HalfProfileMustStartOnTheAxis) {
  try {
    parse_capping("x", "start 0 0\nline 10 0\n", "p.txt", "start 1 10\nline 5 0\nline 0 0\n", "prof.txt");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "prof.txt: a half profile must start and end on the axis x = 0");
  }
}
