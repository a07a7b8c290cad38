#include <gtest/gtest.h>

#include <random>

#include "core/bezier_extraction.hpp"
#include "core/knot_insertion.hpp"
#include "test_shapes.hpp"

using namespace cadnurbs;

TEST(KnotInsertion, CurveShapeUnchangedAt1000Points) {
  const NurbsCurve c = test::full_circle(5.0);
  const NurbsCurve refined = refine_knots(c, {0.25, 0.5, 0.5, 1.7, 2.5, 3.3, 3.9});
  validate(refined, "refined");
  EXPECT_EQ(refined.count(), c.count() + 7);
  for (int i = 0; i < 1000; ++i) {
    const double t = 4.0 * i / 999.0;
    EXPECT_LT((curve_point(c, t) - curve_point(refined, t)).norm(), 1e-12) << t;
  }
}

TEST(KnotInsertion, SurfaceShapeUnchangedAt1000Points) {
  const NurbsSurface s = test::quarter_cylinder(2.0, 3.0);
  NurbsSurface r = refine_knots(s, SurfaceDirection::u, {0.1, 0.5, 0.5, 0.8});
  r = refine_knots(r, SurfaceDirection::v, {0.3, 0.6});
  validate(r, "refined");
  EXPECT_EQ(r.u_count, 7);
  EXPECT_EQ(r.v_count, 4);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int i = 0; i < 1000; ++i) {
    const double u = unit(rng), v = unit(rng);
    EXPECT_LT((surface_point(s, u, v) - surface_point(r, u, v)).norm(), 1e-12);
  }
}

TEST(KnotInsertion, RefiningAtOnceGivesTheNetOfOneAtATime) {
  const NurbsCurve c = test::full_circle(5.0);
  const std::vector<double> knots{0.25, 0.5, 0.5, 1.2, 1.7, 3.3, 3.9};
  NurbsCurve one_by_one = c;
  for (double t : knots) one_by_one = insert_knot(one_by_one, t);
  const NurbsCurve at_once = refine_knots(c, knots);
  ASSERT_EQ(at_once.knots, one_by_one.knots);
  ASSERT_EQ(at_once.count(), one_by_one.count());
  for (int i = 0; i < at_once.count(); ++i) {
    EXPECT_LT((at_once.points[i] - one_by_one.points[i]).norm(), 1e-12) << i;
    EXPECT_NEAR(at_once.weight(i), one_by_one.weight(i), 1e-12) << i;
  }
}

TEST(KnotInsertion, RefinementRefusesMultiplicityAboveDegree) {
  try {
    refine_knots(test::full_circle(1), {0.5, 2.0});
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "knot insertion: knot 2.000000 would get multiplicity 3 above the degree");
  }
}

TEST(KnotInsertion, RefusesKnotOutsideDomain) {
  EXPECT_THROW(insert_knot(test::quarter_circle(1), 1.5), std::runtime_error);
}

TEST(KnotInsertion, RefusesMultiplicityAboveDegree) {
  try {
    insert_knot(test::full_circle(1), 2.0);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "knot insertion: knot 2.000000 would get multiplicity 3 above the degree");
  }
}

TEST(BezierExtraction, CircleSplitsIntoFourExactArcs) {
  const auto pieces = bezier_segments(test::full_circle(2.0));
  ASSERT_EQ(pieces.size(), 4u);
  for (const auto& piece : pieces) {
    EXPECT_EQ(piece.count(), 3);
    for (int i = 0; i <= 50; ++i) {
      const double t = piece.domain_start() + (piece.domain_end() - piece.domain_start()) * i / 50.0;
      EXPECT_NEAR(curve_point(piece, t).norm(), 2.0, 1e-12);
    }
  }
}

TEST(BezierExtraction, CubicSplitsAtEveryInteriorKnot) {
  NurbsCurve c;
  c.order = 4;
  c.knots = {0, 0, 0, 0, 0.3, 0.6, 1, 1, 1, 1};
  c.points = {{0, 0, 0}, {1, 2, 0}, {2, -1, 1}, {3, 3, 2}, {4, 0, 0}, {5, 1, -1}};
  const auto pieces = bezier_segments(c);
  ASSERT_EQ(pieces.size(), 3u);
  for (const auto& piece : pieces)
    for (int i = 0; i <= 20; ++i) {
      const double t = piece.domain_start() + (piece.domain_end() - piece.domain_start()) * i / 20.0;
      EXPECT_LT((curve_point(piece, t) - curve_point(c, t)).norm(), 1e-12);
    }
}
