// Loop subdivision with sharp features against closed forms: creases are uniform cubic B-splines of
// their vertices, flat tagged boxes stay flat, limit points do not move under refinement.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "analysis/subdivision/limit_surface.hpp"

namespace cadnurbs {
namespace {

// A strip folded along a wavy crease c0..cn, with a row of vertices on either side.
struct Strip {
  SubdivisionControlMesh mesh;
  std::vector<int> crease;  // vertex ids along the crease
};

Strip folded_strip(int n) {
  Strip s;
  auto crease_point = [](int i) { return Eigen::Vector3d(i, 0.6 * std::sin(1.3 * i), 0.25 * i * i / 6.0); };
  for (int i = 0; i <= n; ++i) {
    const Eigen::Vector3d c = crease_point(i);
    s.mesh.positions.push_back(c + Eigen::Vector3d(0.1 * i, 1.0, 0.8));   // side A: 3i
    s.mesh.positions.push_back(c);                                         // crease: 3i + 1
    s.mesh.positions.push_back(c + Eigen::Vector3d(-0.2, -1.0, 0.9));    // side B: 3i + 2
    s.crease.push_back(3 * i + 1);
  }
  for (int i = 0; i < n; ++i) {
    const int a0 = 3 * i, c0 = a0 + 1, b0 = a0 + 2, a1 = a0 + 3, c1 = a0 + 4, b1 = a0 + 5;
    s.mesh.triangles.push_back({a0, c0, c1});
    s.mesh.triangles.push_back({a0, c1, a1});
    s.mesh.triangles.push_back({c0, b0, b1});
    s.mesh.triangles.push_back({c0, b1, c1});
    s.mesh.crease_edges.push_back({c0, c1});
  }
  return s;
}

// The uniform cubic B-spline with control points p (knots at the integers) at t in [1, size - 2].
Eigen::Vector3d cubic_bspline(const std::vector<Eigen::Vector3d>& p, double t) {
  const int i = std::min(static_cast<int>(std::floor(t)), static_cast<int>(p.size()) - 3);
  const double u = t - i;
  return (p[i - 1] * std::pow(1 - u, 3) + p[i] * (3 * u * u * u - 6 * u * u + 4) +
          p[i + 1] * (-3 * u * u * u + 3 * u * u + 3 * u + 1) + p[i + 2] * u * u * u) /
         6.0;
}

TEST(SubdivisionRules, CreaseLimitIsTheCubicBSplineOfItsVertices) {
  const Strip strip = folded_strip(6);
  const int levels = 4;
  // Parameters of the crease's vertices, carried through the refinements (edge vertices at midpoints).
  std::map<int, double> parameter;
  for (size_t i = 0; i < strip.crease.size(); ++i) parameter[strip.crease[i]] = static_cast<double>(i);
  ControlMeshTopology level = control_mesh_topology(strip.mesh);
  for (int k = 0; k < levels; ++k) {
    const ControlMeshEdges edges = control_mesh_edges(level);
    for (size_t e = 0; e < edges.ends.size(); ++e) {
      const auto [a, b] = edges.ends[e];
      if (parameter.count(a) && parameter.count(b) && edges.sharp[e] && edges.face_count[e] == 2)
        parameter[level.vertex_count + static_cast<int>(e)] = (parameter[a] + parameter[b]) / 2;
    }
    level = refine_control_mesh(level).fine;
  }
  const int n = static_cast<int>(strip.crease.size()) - 1;
  ASSERT_EQ(parameter.size(), static_cast<size_t>(n * (1 << levels) + 1));

  // The ends are corners (two boundary edges and the crease): the curve interpolates them, which is
  // the B-spline whose phantom end points are the reflections 2 c0 - c1 and 2 cn - cn-1.
  std::vector<Eigen::Vector3d> control{2 * strip.mesh.positions[strip.crease[0]] - strip.mesh.positions[strip.crease[1]]};
  for (const int v : strip.crease) control.push_back(strip.mesh.positions[v]);
  control.push_back(2 * control.back() - control[control.size() - 2]);

  const TriangleMesh limit = evaluate_limit_mesh(subdivision_limit_mesh(control_mesh_topology(strip.mesh), levels), strip.mesh.positions);
  double worst = 0;
  for (const auto& [v, t] : parameter) worst = std::max(worst, (limit.positions[v] - cubic_bspline(control, t + 1)).norm());
  EXPECT_LT(worst, 1e-12);
  // The sides' shape does not leak into the crease: moving side A leaves the crease points as they are.
  Strip moved = strip;
  for (int i = 0; i <= n; ++i) moved.mesh.positions[3 * i] += Eigen::Vector3d(0.3, 2.0, -1.5);
  const TriangleMesh limit_moved =
      evaluate_limit_mesh(subdivision_limit_mesh(control_mesh_topology(moved.mesh), levels), moved.mesh.positions);
  for (const auto& [v, t] : parameter) EXPECT_LT((limit_moved.positions[v] - limit.positions[v]).norm(), 1e-12);
}

SubdivisionControlMesh cube(bool tag_edges) {
  SubdivisionControlMesh m;
  for (int i = 0; i < 8; ++i) m.positions.push_back({(i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0});
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.triangles.push_back({q[0], q[1], q[2]});
    m.triangles.push_back({q[0], q[2], q[3]});
    if (tag_edges)
      for (int k = 0; k < 4; ++k) {
        const int a = q[k], b = q[(k + 1) % 4];
        if (a < b) m.crease_edges.push_back({a, b});
      }
  }
  return m;
}

TEST(SubdivisionRules, TaggedCubeStaysTheCube) {
  const SubdivisionControlMesh box = cube(true);
  ASSERT_EQ(box.crease_edges.size(), 12u);
  const TriangleMesh limit = evaluate_limit_mesh(subdivision_limit_mesh(control_mesh_topology(box), 3), box.positions);
  EXPECT_EQ(limit.triangles.size(), 12u * 64);
  for (const auto& p : limit.positions) {
    EXPECT_NEAR(p.cwiseAbs().maxCoeff(), 1.0, 1e-14);  // on a face of the cube
  }
  EXPECT_NEAR(mesh_area(limit), 24.0, 1e-12);
}

TEST(SubdivisionRules, UntaggedCubeIsRoundedInside) {
  const SubdivisionControlMesh box = cube(false);
  const TriangleMesh limit = evaluate_limit_mesh(subdivision_limit_mesh(control_mesh_topology(box), 3), box.positions);
  double largest = 0;
  for (const auto& p : limit.positions) largest = std::max(largest, p.cwiseAbs().maxCoeff());
  EXPECT_LT(largest, 0.9);  // untagged, no point stays on a corner or edge of the cube (measured 0.865)
}

TEST(SubdivisionRules, LimitPointsDoNotMoveUnderRefinement) {
  // An octahedron (valence 4) with one crease loop around its equator and one corner at a pole.
  SubdivisionControlMesh m;
  m.positions = {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {0, 0, 1.3}, {0.1, 0, -0.9}};
  for (int i = 0; i < 4; ++i) {
    m.triangles.push_back({i, (i + 1) % 4, 4});
    m.triangles.push_back({(i + 1) % 4, i, 5});
    m.crease_edges.push_back({std::min(i, (i + 1) % 4), std::max(i, (i + 1) % 4)});
  }
  m.corner_vertices = {4};
  const ControlMeshTopology top = control_mesh_topology(m);
  const TriangleMesh coarse = evaluate_limit_mesh(subdivision_limit_mesh(top, 0), m.positions);
  const TriangleMesh fine = evaluate_limit_mesh(subdivision_limit_mesh(top, 5), m.positions);
  for (size_t v = 0; v < m.positions.size(); ++v) EXPECT_LT((coarse.positions[v] - fine.positions[v]).norm(), 1e-12) << v;
  EXPECT_EQ((coarse.positions[4] - m.positions[4]).norm(), 0.0);  // a corner is interpolated
  // The smooth pole (valence 4): Loop's mask 1 - 4w, w = 1 / (3 / (8 beta) + 4), beta(4) = 5/32 - 1/16... closed.
  const double beta4 = (5.0 / 8.0 - std::pow(3.0 / 8.0 + std::cos(M_PI / 2) / 4.0, 2)) / 4.0;
  const double w = 1.0 / (3.0 / (8.0 * beta4) + 4);
  Eigen::Vector3d expected = (1 - 4 * w) * m.positions[5];
  for (int i = 0; i < 4; ++i) expected += w * m.positions[i];
  EXPECT_LT((coarse.positions[5] - expected).norm(), 1e-15);
}

TEST(SubdivisionRules, StencilRowsSumToOne) {
  const Strip strip = folded_strip(5);
  const SubdivisionLimitMesh limit = subdivision_limit_mesh(control_mesh_topology(strip.mesh), 3);
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(limit.limit_from_control.cols());
  const Eigen::VectorXd sums = limit.limit_from_control * ones;
  EXPECT_LT((sums - Eigen::VectorXd::Ones(sums.size())).cwiseAbs().maxCoeff(), 1e-14);
}

TEST(SubdivisionRules, RefusesATagThatIsNotAnEdge) {
  SubdivisionControlMesh box = cube(false);
  box.crease_edges.push_back({0, 7});
  try {
    control_mesh_edges(control_mesh_topology(box));
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "control_mesh_edges: crease tag 0-7 is not an edge of the mesh");
  }
}

}  // namespace
}  // namespace cadnurbs
