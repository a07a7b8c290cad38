// Rhino 1's legacy spline and surface records built byte by byte as openNURBS's ReadV1_TCODE_LEGACY_
// SPLSTUFF / SRFSTUFF read them: the clamped-ends flag that stores an end's repeated knots once, Euclidean
// rational points, the surface's v-fastest point order, and the exact refusals.
#include "formats/3dm/legacy_nurbs.hpp"

#include <gtest/gtest.h>

#include "class_chunks.hpp"

namespace cadnurbs::rhino {
namespace {

using testing::ClassData;  // little-endian bytes built by hand

// what() of the ArchiveError `read` throws on `bytes` (a V1 record outside any chunk), or "no error".
template <class Read>
std::string refusal(const std::string& bytes, const char* name, Read read) {
  ArchiveReader reader(bytes, name, 1);
  try {
    read(reader);
  } catch (const ArchiveError& e) {
    return e.what();
  }
  return "no error";
}

// A rational quadratic 2D spline with 4 points, both ends clamped: the stored knots 0, 1, 2 stand for
// openNURBS's 0 0 1 2 2.
ClassData clamped_rational_spline() {
  ClassData b;
  b.put<std::int8_t>(2).put<std::int8_t>(1).put<std::int8_t>(3).put<std::uint16_t>(4);
  b.put<std::uint8_t>(0).put<std::uint8_t>(0);
  b.doubles({0, 0, 3, 2});                              // bounding box
  b.put<std::int8_t>(3);                                // both ends clamped
  b.doubles({0, 1, 2});                                 // first, middle, last knot
  b.doubles({0, 0, 1, 1, 1, 0.5, 2, 1, 0.5, 3, 0, 1});  // x, y, w (Euclidean)
  return b;
}

TEST(LegacyNurbs, ClampedEndsStoreTheirKnotOnceAndRationalPointsAreEuclidean) {
  const std::string bytes = clamped_rational_spline().body;
  ArchiveReader reader(bytes, "spl", 1);
  const NurbsCurve c = read_legacy_spline(reader);
  EXPECT_EQ(reader.offset(), bytes.size());
  EXPECT_EQ(c.dimension, 2);
  EXPECT_EQ(c.order, 3);
  EXPECT_EQ(c.knots, (std::vector<double>{0, 0, 0, 1, 2, 2, 2}));
  ASSERT_EQ(c.count(), 4);
  EXPECT_EQ(c.points[1], Eigen::Vector3d(1, 1, 0));
  EXPECT_EQ(c.points[2], Eigen::Vector3d(2, 1, 0));
  EXPECT_EQ(c.weights, (std::vector<double>{1, 0.5, 0.5, 1}));
}

TEST(LegacyNurbs, AnOrderBelowTwoIsRefusedNamingTheRecordAndOffset) {
  ClassData b;
  b.put<std::int8_t>(3).put<std::int8_t>(0).put<std::int8_t>(1).put<std::uint16_t>(4);
  EXPECT_EQ(refusal(b.body, "spl", read_legacy_spline), "spl: offset 5: legacy spline: order 1 is below 2");
}

TEST(LegacyNurbs, SurfacePointsRunVFastestInTheFileAndUFastestInCore) {
  ClassData b;
  b.put<std::int8_t>(3).put<std::uint8_t>(0).put<std::int8_t>(1).put<std::int8_t>(1);  // degrees 1, 1
  b.put<std::uint16_t>(2).put<std::uint16_t>(1);  // u: 2 spans (3 points), v: 1 span (2 points)
  b.put<std::int8_t>(0).put<std::int8_t>(0);      // not rational
  b.put<std::uint32_t>(0);                        // closed and singular flags
  b.doubles({0, 0, 0, 2, 1, 0});                  // bounding box
  b.doubles({0, 1, 2});                           // u knots (order + count - 2 = 3)
  b.doubles({0, 1});                              // v knots
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j) b.doubles({double(i), double(j), double(10 * i + j)});
  ArchiveReader reader(b.body, "srf", 1);
  const NurbsSurface s = read_legacy_surface(reader);
  EXPECT_EQ(reader.offset(), b.body.size());
  ASSERT_EQ(s.u_count, 3);
  ASSERT_EQ(s.v_count, 2);
  EXPECT_EQ(s.u_knots, (std::vector<double>{0, 0, 1, 2, 2}));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j) EXPECT_EQ(s.point(i, j), Eigen::Vector3d(i, j, 10 * i + j));
}

TEST(LegacyNurbs, ASurfaceWhoseCountsDoNotFitIsRefusedBeforeAnythingIsAllocated) {
  ClassData b;
  b.put<std::int8_t>(3).put<std::uint8_t>(0).put<std::int8_t>(1).put<std::int8_t>(1);
  b.put<std::uint16_t>(65535).put<std::uint16_t>(65535);  // 65536 x 65536 points
  b.put<std::int8_t>(0).put<std::int8_t>(0).put<std::uint32_t>(0);
  b.doubles({0, 0, 0, 1, 1, 1});
  EXPECT_EQ(refusal(b.body, "srf", read_legacy_surface), "srf: offset 62: 65536 doubles need 65536 * 8 bytes, 0 left");
  b.body.append(2 * 65536 * sizeof(double), '\0');  // the knots, then no points
  EXPECT_EQ(refusal(b.body, "srf", read_legacy_surface),
            "srf: offset " + std::to_string(b.body.size()) +
                ": legacy surface: 4294967296 control points need more than the 0 bytes left");
}

}  // namespace
}  // namespace cadnurbs::rhino
