#include <gtest/gtest.h>

#include "core/geometry_error.hpp"
#include "core/trimmed_surface.hpp"

using namespace cadnurbs;

namespace {
TrimLoop unit_square_loop() {
  TrimLoop loop;
  loop.segments.emplace_back(Polyline2D{{{0.1, 0.1}, {0.9, 0.1}, {0.9, 0.9}}});
  loop.segments.emplace_back(Polyline2D{{{0.9, 0.9}, {0.1, 0.9}, {0.1, 0.1}}});
  return loop;
}
TrimmedSurface plane_with(TrimLoop loop) {
  TrimmedSurface t;
  t.surface.u_count = t.surface.v_count = 2;
  t.surface.u_knots = t.surface.v_knots = {0, 0, 1, 1};
  t.surface.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  t.loops.push_back(std::move(loop));
  return t;
}
}  // namespace

TEST(TrimmedSurface, SquareLoopIsClosedAndCounterClockwise) {
  const TrimLoop loop = unit_square_loop();
  EXPECT_EQ(loop_closure_gap(loop), 0.0);
  EXPECT_NEAR(loop_signed_area(loop), 0.64, 1e-15);
  EXPECT_NEAR(loop_signed_area(reversed(loop)), -0.64, 1e-15);
  validate(plane_with(loop), "lid");
}

TEST(TrimmedSurface, ReversingALoopReversesItsEdgeReferences) {
  TrimLoop loop = unit_square_loop();
  loop.edges = {{3, false}, {7, true}};
  const TrimLoop r = reversed(loop);
  EXPECT_EQ(r.edges, (std::vector<TrimEdgeRef>{{7, false}, {3, true}}));
  EXPECT_EQ(segment_start(r.segments[0]), segment_end(loop.segments[1]));
}

TEST(TrimmedSurface, RefusesEdgeReferenceCountMismatch) {
  TrimLoop loop = unit_square_loop();
  loop.edges = {{1, false}};
  try {
    validate(plane_with(loop), "face 4");
    FAIL();
  } catch (const GeometryError& e) {
    EXPECT_STREQ(e.what(), "face 4 loop 0: 1 edge references for 2 segments");
  }
}

TEST(TrimmedSurface, RefusesOpenLoop) {
  TrimLoop loop = unit_square_loop();
  std::get<Polyline2D>(loop.segments[1]).points.back() = {0.1, 0.2};
  try {
    validate(plane_with(loop), "lid");
    FAIL();
  } catch (const GeometryError& e) {
    EXPECT_EQ(e.entity(), "lid loop 0");
    EXPECT_EQ(e.reason(), "does not close: gap 0.100000 between segments");
  }
}
