// DomainTriangulation against closed forms: the triangles inside the loops (even-odd) cover exactly
// the area between them, counter-clockwise, whatever the loops' directions, the points added inside
// and the constrained edges split afterwards.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/tessellation/domain_triangulation.hpp"
#include "core/polygon_2d.hpp"

namespace cadnurbs {
namespace {

double signed_area(const DomainTriangulation& dt, const std::array<int, 3>& t) {
  const Eigen::Vector2d a = dt.uv(t[0]), b = dt.uv(t[1]), c = dt.uv(t[2]);
  return 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
}

// Sum of the inside triangles' areas; every one must be counter-clockwise.
double inside_area(const DomainTriangulation& dt) {
  double sum = 0;
  for (const auto& t : dt.inside_triangles()) {
    const double a = signed_area(dt, t);
    EXPECT_GT(a, 0) << t[0] << " " << t[1] << " " << t[2];
    sum += a;
  }
  return sum;
}

// The square [lo, hi]^2 as a loop of inserted vertices, counter-clockwise (or clockwise).
std::vector<int> square(DomainTriangulation& dt, double lo, double hi, bool counter_clockwise) {
  std::vector<int> ids{dt.insert({lo, lo}), dt.insert({hi, lo}), dt.insert({hi, hi}), dt.insert({lo, hi})};
  if (!counter_clockwise) std::reverse(ids.begin(), ids.end());
  return ids;
}

TEST(DomainTriangulation, SquareWithAHoleHasTheAreaBetween) {
  for (bool hole_ccw : {false, true}) {  // even-odd: the hole's direction does not matter
    DomainTriangulation dt(1, 1);
    dt.insert_loop(square(dt, 0, 1, true));
    dt.insert_loop(square(dt, 0.25, 0.75, hole_ccw));
    EXPECT_EQ(dt.vertex_count(), 8);
    EXPECT_NEAR(inside_area(dt), 1 - 0.25, 1e-15) << hole_ccw;
  }
}

TEST(DomainTriangulation, PointsAddedLaterKeepTheArea) {
  DomainTriangulation dt(1, 1);
  dt.insert_loop(square(dt, 0, 1, true));
  dt.insert_loop(square(dt, 0.25, 0.75, false));
  const int first = dt.insert({0.1, 0.1});
  for (int j = 1; j < 10; ++j)
    for (int i = 1; i < 10; ++i) dt.insert({0.1 * i, 0.1 * j});  // inside the hole too
  EXPECT_EQ(dt.insert({0.1, 0.1}), first);  // an existing point keeps its id
  EXPECT_EQ(dt.uv(first), Eigen::Vector2d(0.1, 0.1));
  EXPECT_NEAR(inside_area(dt), 0.75, 1e-14);
  // No inside triangle reaches into the hole.
  for (const auto& t : dt.inside_triangles()) {
    const Eigen::Vector2d centre = (dt.uv(t[0]) + dt.uv(t[1]) + dt.uv(t[2])) / 3.0;
    EXPECT_FALSE(centre.x() > 0.25 && centre.x() < 0.75 && centre.y() > 0.25 && centre.y() < 0.75);
  }
}

TEST(DomainTriangulation, RegularPolygonHasItsClosedFormArea) {
  // A regular 64-gon of radius 2 in a domain stretched 1000:1 in v (scaled back for Delaunay).
  constexpr int n = 64;
  DomainTriangulation dt(1, 1e-3);
  std::vector<int> ids;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * M_PI * k / n;
    ids.push_back(dt.insert({2 * std::cos(a), 2000 * std::sin(a)}));
  }
  dt.insert_loop(ids);
  EXPECT_NEAR(inside_area(dt), 1000 * 0.5 * n * 4 * std::sin(2 * M_PI / n), 1e-9);
}

TEST(DomainTriangulation, SplittingAConstrainedEdgeKeepsTheArea) {
  DomainTriangulation dt(1, 1);
  const std::vector<int> outer = square(dt, 0, 1, true);
  dt.insert_loop(outer);
  dt.insert({0.5, 0.5});
  ASSERT_TRUE(dt.is_constrained(outer[0], outer[1]));
  EXPECT_FALSE(dt.is_constrained(outer[0], outer[2]));  // a diagonal, if it is an edge at all
  const int m = dt.split_constrained_edge(outer[0], outer[1], {0.5, 0});
  EXPECT_EQ(dt.uv(m), Eigen::Vector2d(0.5, 0));
  EXPECT_TRUE(dt.is_constrained(outer[0], m));
  EXPECT_TRUE(dt.is_constrained(m, outer[1]));
  EXPECT_FALSE(dt.is_constrained(outer[0], outer[1]));
  EXPECT_NEAR(inside_area(dt), 1.0, 1e-15);
  EXPECT_EQ(dt.inside_triangles().size(), 5u);  // 4 vertices, the centre and the split point
}

// LED_D10.0mm.step's plane: a round hole touches the outer loop, which runs along the domain's edge, and
// the two loops share the tiny side between the points where they meet. One CGAL constraint there, two
// loop sides: even-odd it bounds nothing, so the hole stays a hole (its triangles were counted in when
// crossing that side went one level deeper: the face's mesh had 6x its area).
TEST(DomainTriangulation, AHoleSharingASideWithItsOuterLoopStaysAHole) {
  for (const bool split_it : {false, true}) {
    DomainTriangulation dt(1, 1);
    const int p = dt.insert({0, 0.5}), q = dt.insert({0, 0.5 + 1e-8});  // the shared side, on the edge u = 0
    const int a = dt.insert({0, 0}), b = dt.insert({1, 0}), c = dt.insert({1, 1}), d = dt.insert({0, 1});
    dt.insert_loop({a, b, c, d, q, p});  // the unit square through p and q, counter-clockwise
    const int e = dt.insert({0.25, 0.25}), f = dt.insert({0.25, 0.75});
    dt.insert_loop({p, q, f, e});  // the hole: a triangle-like quad with the side p q on u = 0
    if (split_it) dt.split_constrained_edge(p, q, {0, 0.5 + 5e-9});
    const double hole = std::abs(polygon_signed_area({dt.uv(p), dt.uv(q), dt.uv(f), dt.uv(e)}));  // 0.0625
    EXPECT_NEAR(inside_area(dt), 1.0 - hole, 1e-12) << "split " << split_it;
  }
}

}  // namespace
}  // namespace cadnurbs
