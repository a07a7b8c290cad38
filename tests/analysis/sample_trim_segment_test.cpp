// Trim sampling: chords within the deviation, and not many more of them than the curve needs.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/eval/sample_trim_segment.hpp"
#include "analysis_shapes.hpp"

namespace cadnurbs {
namespace {

std::vector<TrimSample> sample_on(const NurbsSurface& surface, const TrimSegment& segment, double d) {
  const SurfaceEvaluator eval(surface);
  const SurfaceDeviationBound bound = surface_deviation_bound(surface);
  const Eigen::Vector2d a = segment_uv(segment, segment_t0(segment)), b = segment_uv(segment, segment_t1(segment));
  return sample_trim_segment(eval, bound, segment, d, eval.point(a.x(), a.y()), eval.point(b.x(), b.y()));
}

// A circle of radius 10 on the plane: every chord's exact sagitta is within D; there are no fewer
// chords than sagittas of 0.9 D allow (the sampled criterion) and at most one a quarter arc more than
// the fewest of sagitta 0.7 D (what re-placed chords aim at).
TEST(SampleTrimSegment, ACircleGetsNearlyTheFewestChords) {
  const double size = 20, radius = 10, d = 0.01;
  const TrimmedSurface plane = test::trimmed_square(size, 0.5, 0.25);
  const auto samples = sample_on(plane.surface, test::circle_2d({0.5, 0.5}, 0.5), d);
  const Eigen::Vector3d centre(10, 10, 0);
  for (size_t k = 0; k + 1 < samples.size(); ++k) {
    const double sagitta = radius - (0.5 * (samples[k].point + samples[k + 1].point) - centre).norm();
    EXPECT_LE(sagitta, d) << "chord " << k;
  }
  auto fewest = [&](double s) { return std::ceil(M_PI / std::acos(1 - s / radius)); };
  const double chords = static_cast<double>(samples.size() - 1);
  EXPECT_GE(chords, fewest(0.9 * d));     // 75
  EXPECT_LE(chords, fewest(0.7 * d) + 4);  // 84 + 4
}

// A straight (u,v) line written as a degree-1 curve with 40 knots of its own (each a C0 knot): on a
// plane one chord holds it.
TEST(SampleTrimSegment, ADegreeOnePcurveOnAPlaneIsOneChord) {
  const TrimmedSurface plane = test::trimmed_square(20, 0.5, 0.25);
  NurbsCurve line;
  line.dimension = 2;
  line.order = 2;
  line.knots = {0, 0};
  for (int k = 0; k <= 40; ++k) {
    const double s = k / 40.0;
    line.points.emplace_back(0.1 + 0.8 * s, 0.2 + 0.5 * s, 0);
    if (k > 0 && k < 40) line.knots.push_back(s);
  }
  line.knots.insert(line.knots.end(), {1, 1});
  const auto samples = sample_on(plane.surface, line, 0.01);
  ASSERT_EQ(samples.size(), 2u);
  EXPECT_EQ(samples.back().t, 1.0);
}

// A roof folded along the C0 knot line u = 0.5: a straight polyline across the fold has a corner in 3D
// exactly there (t = 0.5 / 0.8), which becomes its one interior sample.
TEST(SampleTrimSegment, APolylineAcrossASurfaceCreaseIsSampledAtTheCrease) {
  NurbsSurface roof;
  roof.u_order = roof.v_order = 2;
  roof.u_count = 3, roof.v_count = 2;
  roof.u_knots = {0, 0, 0.5, 1, 1};
  roof.v_knots = {0, 0, 1, 1};
  roof.points = {{0, 0, 0}, {1, 0, 1}, {2, 0, 0}, {0, 1, 0}, {1, 1, 1}, {2, 1, 0}};
  const auto samples = sample_on(roof, Polyline2D{{{0.0, 0.5}, {0.8, 0.5}}}, 0.001);
  ASSERT_EQ(samples.size(), 3u);
  EXPECT_EQ(samples[1].t, 0.625);
  EXPECT_NEAR((samples[1].point - Eigen::Vector3d(1, 0.5, 1)).norm(), 0.0, 1e-12);
}

}  // namespace
}  // namespace cadnurbs
