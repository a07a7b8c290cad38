// The curve classes on Rhino-written corpus files (found by scanning for their class ids, so these tests
// do not depend on the table and Brep readers) and on hand-built class data: exact arcs, polylines through
// their points, polycurves joined without changing shape, and the refusals' messages.
#include "formats/3dm/curve_objects.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "formats/3dm/rhino_object.hpp"
#include "formats/3dm/surface_objects.hpp"
#include "formats/3dm/typecodes.hpp"
#include "tests/3dm/class_chunks.hpp"

namespace cadnurbs::rhino {
namespace {

using testing::class_chunk_offsets;
using testing::ClassData;
using testing::corpus_file;
using testing::error_of;
using testing::line;
using testing::object_chunk;
using testing::reader_at_class_data;

constexpr const char* kNurbsCurveId = "4ED7D4DD-E947-11D3-BFE5-0010830122F0";
constexpr const char* kLegacyNurbsCurveId = "5EAF1119-0B51-11D4-BFFE-0010830122F0";  // TL_NurbsCurve
constexpr const char* kArcCurveId = "CF33BE2A-09B4-11D4-BFFB-0010830122F0";
constexpr const char* kPolylineCurveId = "4ED7D4E6-E947-11D3-BFE5-0010830122F0";
constexpr const char* kPolyCurveId = "4ED7D4E0-E947-11D3-BFE5-0010830122F0";
constexpr const char* kNurbsSurfaceId = "4ED7D4DE-E947-11D3-BFE5-0010830122F0";


// The arc's fields as the file stores them, read field by field (independently of read_arc_curve).
struct RawArc {
  Eigen::Vector3d origin, x, y, z;
  double radius, a0, a1, t0, t1;
};
RawArc raw_arc(ArchiveReader r) {
  RawArc a;
  r.u8();  // chunk version
  a.origin = r.point3();
  a.x = r.point3();
  a.y = r.point3();
  a.z = r.point3();
  r.skip(4 * 8);
  a.radius = r.f64();
  r.skip(9 * 8);
  a.a0 = r.f64();
  a.a1 = r.f64();
  a.t0 = r.f64();
  a.t1 = r.f64();
  return a;
}

// Rhino's own arcs (v5_extrusions: 3 objects + 3 extrusion profiles; v5_teapot: 4 in Breps): every point
// of the NURBS at the radius from the centre and in the arc's plane, ends at the arc's end angles, the
// domain the file's, and arc_nurbs_parameter finds the arc's own (angle-linear) points.
TEST(CurveObjects, ArcCurvesAreExactRationalQuadratics) {
  int arcs = 0;
  for (const char* file : {"v5_extrusions.3dm", "v5_teapot.3dm"}) {
    const std::string bytes = corpus_file(file);
    for (const std::size_t at : class_chunk_offsets(bytes, kArcCurveId)) {
      ++arcs;
      const RawArc raw = raw_arc(reader_at_class_data(bytes, file, at));
      ArchiveReader reader = reader_at_class_data(bytes, file, at);
      const NurbsCurve c = read_arc_curve(reader);
      const double angle = raw.a1 - raw.a0;
      const int spans = angle <= 0.5 * std::numbers::pi * (1 + 1e-8) ? 1 : angle <= std::numbers::pi * (1 + 1e-8) ? 2 : 4;
      EXPECT_EQ(c.order, 3);
      ASSERT_EQ(c.count(), 2 * spans + 1);
      ASSERT_TRUE(c.is_rational());
      EXPECT_EQ(c.knots.front(), raw.t0);
      EXPECT_EQ(c.knots.back(), raw.t1);
      EXPECT_DOUBLE_EQ(c.weights[1], std::cos(0.5 * angle / spans));
      const double tolerance = 1e-12 * std::max(1.0, raw.radius + raw.origin.norm());
      for (int i = 0; i <= 64; ++i) {
        const double s = raw.t0 + (raw.t1 - raw.t0) * i / 64.0;
        const Eigen::Vector3d p = curve_point(c, s);
        EXPECT_NEAR((p - raw.origin).norm(), raw.radius, tolerance) << file << " arc at " << at << " s " << s;
        EXPECT_NEAR((p - raw.origin).dot(raw.z), 0.0, tolerance);
        // The arc's own point at s: its angle moves linearly with s.
        CircularArc arc{raw.origin, raw.x, raw.y, raw.radius, raw.a0, raw.a1};
        const double theta = raw.a0 + (s - raw.t0) / (raw.t1 - raw.t0) * angle;
        const Eigen::Vector3d own = raw.origin + raw.radius * (std::cos(theta) * raw.x + std::sin(theta) * raw.y);
        EXPECT_LT((curve_point(c, arc_nurbs_parameter(arc, raw.t0, raw.t1, s)) - own).norm(), tolerance);
      }
      if (std::abs(angle - 2 * std::numbers::pi) <= 1e-12) {
        EXPECT_EQ(c.points.front(), c.points.back());
      }
    }
  }
  EXPECT_EQ(arcs, 10);
}

// The V2 example's trimmed surface: three 2D trims (a closed triangle in the surface's (u, v) domain) and
// three 3D edges, all order 2 lines; each edge runs between the surface's points at its trim's ends.
TEST(CurveObjects, TrimsAndEdgesOfTheV2TrimmedSurface) {
  const std::string bytes = corpus_file("v2_my_trimmed_surface.3dm");
  const auto offsets = class_chunk_offsets(bytes, kNurbsCurveId);
  ASSERT_EQ(offsets.size(), 6u);
  std::vector<NurbsCurve> curves;
  for (const std::size_t at : offsets) {
    ArchiveReader reader = reader_at_class_data(bytes, "v2", at);
    curves.push_back(read_nurbs_curve(reader));
  }
  const auto surface_at = class_chunk_offsets(bytes, kNurbsSurfaceId);
  ASSERT_EQ(surface_at.size(), 1u);
  ArchiveReader surface_reader = reader_at_class_data(bytes, "v2", surface_at[0]);
  const NurbsSurface surface = read_nurbs_surface(surface_reader);
  for (int i = 0; i < 3; ++i) {
    const NurbsCurve& trim = curves[i];
    const NurbsCurve& edge = curves[i + 3];
    EXPECT_EQ(trim.dimension, 2);
    EXPECT_EQ(edge.dimension, 3);
    EXPECT_EQ(trim.order, 2);
    ASSERT_EQ(trim.count(), 2);
    EXPECT_EQ(trim.knots.size(), 4u);
    EXPECT_EQ(trim.knots[0], 0.0);
    EXPECT_EQ(trim.knots[1], 0.0);
    EXPECT_EQ(trim.knots[2], trim.knots[3]);
    EXPECT_EQ(trim.knots, edge.knots);
    EXPECT_EQ(trim.points[1], curves[(i + 1) % 3].points[0]);  // the loop closes
    for (int end = 0; end < 2; ++end) {
      const Eigen::Vector3d uv = trim.points[end];
      EXPECT_LT((surface_point(surface, uv.x(), uv.y()) - edge.points[end]).norm(), 1e-12);
    }
  }
  EXPECT_EQ(curves[0].points[0], Eigen::Vector3d(1, 2, 0));
  EXPECT_EQ(curves[1].points[0], Eigen::Vector3d(9, 1.5, 0));
  EXPECT_EQ(curves[2].points[0], Eigen::Vector3d(7, 8, 0));
}

// Rhino 1 era TL_NurbsCurve objects (demoted to ON_NurbsCurve) and the polylines of v5_extrusions, both
// also nested in its extrusions.
TEST(CurveObjects, LegacyNurbsCurvesAndPolylines) {
  const std::string bytes = corpus_file("v5_extrusions.3dm");
  const auto legacy = class_chunk_offsets(bytes, kLegacyNurbsCurveId);
  ASSERT_EQ(legacy.size(), 10u);
  ArchiveReader first_reader = reader_at_class_data(bytes, "v5", legacy[0]);
  const NurbsCurve first = read_nurbs_curve(first_reader);
  EXPECT_EQ(first.order, 2);
  EXPECT_EQ(first.count(), 5);
  EXPECT_EQ(first.knots.size(), 7u);
  EXPECT_EQ(first.knots.front(), 42.911155671659479);
  EXPECT_EQ(first.knots[2], 48.981408650913174);
  EXPECT_EQ(first.knots.back(), 59.557416418891265);
  EXPECT_EQ(first.points.front(), first.points.back());  // a closed rectangle
  for (int i = 0; i < first.count(); ++i) EXPECT_EQ(curve_point(first, first.knots[i + 1]), first.points[i]);
  for (const std::size_t at : legacy) {
    ArchiveReader reader = reader_at_class_data(bytes, "v5", at);
    const NurbsCurve c = read_nurbs_curve(reader);
    EXPECT_EQ(c.knots.size(), static_cast<std::size_t>(c.count() + c.order));
    EXPECT_EQ(c.knots[0], c.knots[1]);  // the end knot added once more
  }

  const auto polylines = class_chunk_offsets(bytes, kPolylineCurveId);
  ASSERT_EQ(polylines.size(), 4u);  // 2 objects and 2 extrusion profiles
  for (const std::size_t at : polylines) {
    // The raw points and parameters, read field by field.
    ArchiveReader raw = reader_at_class_data(bytes, "v5", at);
    raw.u8();
    std::vector<Eigen::Vector3d> points(raw.count(24));
    for (auto& p : points) p = raw.point3();
    const std::vector<double> params = raw.doubles(raw.count(8));
    ArchiveReader reader = reader_at_class_data(bytes, "v5", at);
    const NurbsCurve c = read_polyline_curve(reader);
    ASSERT_EQ(c.count(), static_cast<int>(points.size()));
    EXPECT_EQ(c.order, 2);
    EXPECT_EQ(std::vector<double>(c.knots.begin() + 1, c.knots.end() - 1), params);
    for (std::size_t i = 0; i < points.size(); ++i) EXPECT_EQ(curve_point(c, params[i]), points[i]);
  }
}

// Rational CVs: the Euclidean point is the homogeneous one times 1 / w, bit for bit (openNURBS's GetCV).
TEST(CurveObjects, EuclideanPointsAreHomogeneousTimesReciprocalWeight) {
  const std::string bytes = corpus_file("v5_teapot.3dm");
  int rational = 0;
  for (const std::size_t at : class_chunk_offsets(bytes, kNurbsCurveId)) {
    ArchiveReader raw = reader_at_class_data(bytes, "teapot", at);
    raw.u8();
    const int dimension = raw.i32();
    const bool is_rational = raw.i32() != 0;
    if (!is_rational) continue;
    ++rational;
    raw.skip(2 * 4 + 2 * 4 + 6 * 8);
    raw.skip(8 * raw.count(8));
    const std::size_t count = raw.count(8 * (dimension + 1));
    ArchiveReader reader = reader_at_class_data(bytes, "teapot", at);
    const NurbsCurve c = read_nurbs_curve(reader);
    ASSERT_EQ(c.count(), static_cast<int>(count));
    for (std::size_t i = 0; i < count; ++i) {
      double h[4];
      for (int d = 0; d <= dimension; ++d) h[d] = raw.f64();
      const double r = 1.0 / h[dimension];
      EXPECT_EQ(c.weights[i], h[dimension]);
      EXPECT_EQ(c.points[i].x(), h[0] * r);
      EXPECT_EQ(c.points[i].y(), h[1] * r);
      EXPECT_EQ(c.points[i].z(), dimension == 3 ? h[2] * r : 0.0);
    }
  }
  EXPECT_GT(rational, 10);
}

// The teapot's 30 polycurves: the joined NURBS follows each segment (read on its own with read_object,
// mapped affinely onto its piece of the polycurve's domain) within 1e-12 of the model's size.
TEST(CurveObjects, PolyCurvesJoinTheirSegmentsExactly) {
  const std::string bytes = corpus_file("v5_teapot.3dm");
  const auto offsets = class_chunk_offsets(bytes, kPolyCurveId);
  ASSERT_EQ(offsets.size(), 30u);
  for (const std::size_t at : offsets) {
    ArchiveReader raw = reader_at_class_data(bytes, "teapot", at);
    raw.u8();
    const int segment_count = raw.i32();
    raw.skip(2 * 4 + 6 * 8);
    const std::vector<double> breaks = raw.doubles(raw.count(8));
    ASSERT_EQ(breaks.size(), static_cast<std::size_t>(segment_count) + 1);
    std::vector<NurbsCurve> segments;
    for (int i = 0; i < segment_count; ++i) segments.push_back(std::get<NurbsCurve>(read_object(raw)));

    ArchiveReader reader = reader_at_class_data(bytes, "teapot", at);
    const NurbsCurve joined = read_poly_curve(reader);
    EXPECT_EQ(joined.domain_start(), breaks.front());
    EXPECT_EQ(joined.domain_end(), breaks.back());
    int highest = 2;
    for (const auto& s : segments) highest = std::max(highest, s.order);
    EXPECT_EQ(joined.order, highest);
    for (int i = 0; i < segment_count; ++i) {
      const NurbsCurve& s = segments[i];
      for (int k = 0; k <= 16; ++k) {
        const double f = k / 16.0;
        const Eigen::Vector3d expected = curve_point(s, s.domain_start() + f * (s.domain_end() - s.domain_start()));
        const Eigen::Vector3d got = curve_point(joined, breaks[i] + f * (breaks[i + 1] - breaks[i]));
        EXPECT_LT((got - expected).norm(), 1e-12 * 400.0) << "polycurve at " << at << " segment " << i << " f " << f;
      }
    }
  }
}


// An unclamped (uniform) cubic is clamped without changing shape; a line, a quarter arc and that cubic
// join into one rational cubic with C0 joints at the breaks.
TEST(CurveObjects, ClampAndJoinKeepTheShape) {
  NurbsCurve cubic;
  cubic.order = 4;
  cubic.knots = {0, 1, 2, 3, 4, 5, 6, 7, 8};
  cubic.points = {{0, 0, 0}, {1, 2, 0}, {3, 3, 1}, {4, 0, 2}, {6, 1, 0}};
  const NurbsCurve c = clamped(cubic);
  validate(c, "clamped");
  EXPECT_EQ(c.knots.front(), 3.0);
  EXPECT_EQ(c.knots[3], 3.0);
  EXPECT_EQ(c.knots.back(), 5.0);
  EXPECT_EQ(c.knots[c.knots.size() - 4], 5.0);
  for (int k = 0; k <= 20; ++k) {
    const double t = 3.0 + 2.0 * k / 20;
    EXPECT_LT((curve_point(c, t) - curve_point(cubic, t)).norm(), 1e-13);
  }

  const NurbsCurve first = line({-1, 0, 0}, {1, 0, 0}, 0.0, 2.0);
  const NurbsCurve arc = arc_as_nurbs(CircularArc{{1, 1, 0}, {0, -1, 0}, {1, 0, 0}, 1.0, 0.0, std::numbers::pi / 2}, 5, 6, 3);
  const Eigen::Vector3d arc_end = curve_point(arc, 6.0);
  NurbsCurve third = cubic;
  for (auto& p : third.points) p += arc_end - curve_point(cubic, 3.0);
  const std::vector<NurbsCurve> segments = {first, arc, third};
  const std::vector<double> breaks = {10.0, 11.0, 13.0, 14.0};
  const NurbsCurve joined = join_segments(segments, breaks);
  validate(joined, "joined");
  EXPECT_EQ(joined.order, 4);
  EXPECT_TRUE(joined.is_rational());
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k <= 16; ++k) {
      const double f = k / 16.0;
      const NurbsCurve& s = segments[i];
      const Eigen::Vector3d expected = curve_point(s, s.domain_start() + f * (s.domain_end() - s.domain_start()));
      EXPECT_LT((curve_point(joined, breaks[i] + f * (breaks[i + 1] - breaks[i])) - expected).norm(), 1e-13)
          << "segment " << i << " f " << f;
    }
  // The joints are knots of multiplicity 3 (the degree): C0 there.
  EXPECT_EQ(std::count(joined.knots.begin(), joined.knots.end(), 11.0), 3);
  EXPECT_EQ(std::count(joined.knots.begin(), joined.knots.end(), 13.0), 3);
}



// ON_NurbsCurve data: version 1.0, dim, is_rat, order, cv_count, 2 reserved, bbox, knots, CVs.
ClassData nurbs_curve_data(int order, int cv_count, bool rational, std::initializer_list<double> knots) {
  ClassData d;
  d.put(std::uint8_t{0x10}).put(3).put(rational ? 1 : 0).put(order).put(cv_count).put(0).put(0);
  d.doubles({0, 0, 0, 0, 0, 0});
  d.put(static_cast<int>(knots.size())).doubles(knots);
  return d;
}

TEST(CurveObjects, RefusesBadNurbsCurves) {
  const std::string prefix = "hand.3dm: chunk 0x00027FFA at offset 0: ON_NurbsCurve: ";
  ClassData decreasing = nurbs_curve_data(2, 3, false, {0, 2, 1});
  decreasing.put(3).doubles({0, 0, 0, 1, 0, 0, 2, 0, 0});
  EXPECT_EQ(error_of(decreasing.chunk(), read_nurbs_curve),
            prefix + "knot 3 (1) is smaller than knot 2 (2); knots must not decrease");

  ClassData zero_weight = nurbs_curve_data(2, 2, true, {0, 1});
  zero_weight.put(2).doubles({0, 0, 0, 1, 1, 0, 0, 0});
  EXPECT_EQ(error_of(zero_weight.chunk(), read_nurbs_curve),
            prefix + "weight of control point 1 is 0; weights must be positive");

  EXPECT_EQ(error_of(nurbs_curve_data(1, 2, false, {0}).chunk(), read_nurbs_curve), prefix + "order 1 is below 2");

  ClassData too_many = nurbs_curve_data(2, 1000, false, {});
  EXPECT_EQ(error_of(too_many.chunk(), read_nurbs_curve),
            prefix + "0 knots stored, order 2 and 1000 control points need 1000");
  ClassData past_chunk = nurbs_curve_data(2, 2, false, {0, 1});
  past_chunk.put(1000).doubles({0, 0, 0});
  EXPECT_EQ(error_of(past_chunk.chunk(), read_nurbs_curve),
            prefix + "1000 control points of 24 bytes need more than the 24 bytes left");

  ClassData version2;
  version2.put(std::uint8_t{0x20});
  EXPECT_EQ(error_of(version2.chunk(), read_nurbs_curve), prefix + "chunk version 2.0 (only 1.x is read)");
}

TEST(CurveObjects, RefusesBadArcsAndPolylines) {
  ClassData arc;  // a circle of radius 0
  arc.put(std::uint8_t{0x10}).doubles({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0});
  arc.doubles({0, 0, 0, 0, 0, 0, 0, 0, 0}).doubles({0, 1}).doubles({0, 1}).put(3);
  EXPECT_EQ(error_of(arc.chunk(), read_arc_curve),
            "hand.3dm: chunk 0x00027FFA at offset 0: ON_ArcCurve: radius 0 is not positive");

  ClassData polyline;
  polyline.put(std::uint8_t{0x10}).put(2).doubles({0, 0, 0, 1, 0, 0}).put(2).doubles({1, 1}).put(3);
  EXPECT_EQ(error_of(polyline.chunk(), read_polyline_curve),
            "hand.3dm: chunk 0x00027FFA at offset 0: ON_PolylineCurve: parameter 1 (1) does not exceed the one "
            "before (1)");
}

// A polycurve whose one segment is a polycurve whose one segment is ... 200 deep: refused at the nesting
// limit, before the stack is at risk. Two levels read fine.
TEST(CurveObjects, RefusesPolyCurvesNestedTooDeep) {
  ClassData line_data;
  line_data.put(std::uint8_t{0x10}).doubles({0, 0, 0, 1, 0, 0}).doubles({0, 1}).put(3);
  std::string inner = object_chunk("4ED7D4DB-E947-11D3-BFE5-0010830122F0", line_data.body);
  ClassData poly;  // one segment over [0, 1]
  poly.put(std::uint8_t{0x10}).put(1).put(0).put(0).doubles({0, 0, 0, 0, 0, 0}).put(2).doubles({0, 1});
  const std::string two_levels_bytes = object_chunk(kPolyCurveId, poly.body, inner);
  ArchiveReader two_levels_reader(two_levels_bytes, "hand.3dm", 70);
  const NurbsCurve two_levels = std::get<NurbsCurve>(read_object(two_levels_reader));
  EXPECT_EQ(two_levels.points[1], Eigen::Vector3d(1, 0, 0));
  for (int level = 0; level < 200; ++level) inner = object_chunk(kPolyCurveId, poly.body, inner);
  ArchiveReader deep(inner, "hand.3dm", 70);
  try {
    read_object(deep);
    ADD_FAILURE() << "200 nested polycurves read";
  } catch (const ArchiveError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(": ON_PolyCurve: segment 0 would nest deeper than 64 chunks"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace cadnurbs::rhino
