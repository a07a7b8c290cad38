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

// A side whose image stands still over a stretch (four control points of the side's column coincide:
// robot_jme2.x3dv's body): there every chord is a few ulps long and its "sagitta" is rounding, which the
// bulge criterion (sagitta above 0.3 of the chord) refused down to 1e-12 of the range, 10^11 samples
// and std::bad_alloc. The still stretch is now a chord like any other.
TEST(SampleTrimSegment, ASideStandingStillOverAStretchIsFewChords) {
  NurbsSurface body;
  body.u_order = 3, body.v_order = 4;
  body.u_count = 3, body.v_count = 7;
  body.u_knots = {0, 0, 0, 1, 1, 1};
  body.v_knots = {0, 0, 0, 0, 1, 2, 3, 4, 4, 4, 4};
  const Eigen::Vector3d still(0.00000005, -1.02834951, -1.96035683);
  for (int j = 0; j < 7; ++j) {
    const double z = 0.37 * j - 1.3;
    body.points.emplace_back(-0.99999994, 0.1 * j, z);
    body.points.emplace_back(-0.72949296, -0.72715288 + 0.01 * j, z + 0.2);
    body.points.push_back(j >= 2 && j <= 5 ? still : Eigen::Vector3d(0.87539160, 0.3 * j, z));
    for (double w : {1.0, 0.70710676, 1.0}) body.weights.push_back(w);
  }
  const auto samples = sample_on(body, Polyline2D{{{1.0, 0.0}, {1.0, 4.0}}}, 0.00737842);
  EXPECT_LT(samples.size(), 200u);
  size_t on_the_still_point = 0;
  for (const auto& s : samples) on_the_still_point += (s.point - still).norm() < 1e-12;
  EXPECT_LE(on_the_still_point, 3u);  // the stretch's ends, and at most one more
}

}  // namespace
}  // namespace cadnurbs
