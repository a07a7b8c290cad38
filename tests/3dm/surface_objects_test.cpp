// The surface classes on Rhino-written corpus files (found by scanning for their class ids) and on
// hand-built data: the NURBS surface's CV grid order, planes, exact revolutions, sums, and refusals.
#include "formats/3dm/surface_objects.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "formats/3dm/curve_objects.hpp"
#include "formats/3dm/rhino_object.hpp"
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

constexpr const char* kNurbsSurfaceId = "4ED7D4DE-E947-11D3-BFE5-0010830122F0";
constexpr const char* kPlaneSurfaceId = "4ED7D4DF-E947-11D3-BFE5-0010830122F0";
constexpr const char* kRevSurfaceId = "A16220D3-163B-11D4-8000-0010830122F0";


// openNURBS's example_write.cpp writes this surface: order 3 x 4, 3 x 5 CVs, CV(i, j) = (i, j, i - j),
// u knots {0, 0, 1, 1}, v knots {0, 0, 0, 1.5, 2, 2, 2} (without the end knots). The file's v-fastest CV
// order must come out u-fastest.
TEST(SurfaceObjects, TheExampleNurbsSurface) {
  const std::string bytes = corpus_file("v7_my_surfaces.3dm");
  const auto offsets = class_chunk_offsets(bytes, kNurbsSurfaceId);
  ASSERT_EQ(offsets.size(), 1u);
  ArchiveReader reader = reader_at_class_data(bytes, "v7", offsets[0]);
  const NurbsSurface s = read_nurbs_surface(reader);
  EXPECT_EQ(s.u_order, 3);
  EXPECT_EQ(s.v_order, 4);
  ASSERT_EQ(s.u_count, 3);
  ASSERT_EQ(s.v_count, 5);
  EXPECT_FALSE(s.is_rational());
  EXPECT_EQ(s.u_knots, (std::vector<double>{0, 0, 0, 1, 1, 1}));
  EXPECT_EQ(s.v_knots, (std::vector<double>{0, 0, 0, 0, 1.5, 2, 2, 2, 2}));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 5; ++j) EXPECT_EQ(s.point(i, j), Eigen::Vector3d(i, j, i - j)) << i << ", " << j;
  // Corners of a clamped surface are its corner CVs; z = u - v holds everywhere (the CVs are linear in
  // i and j, and the knots give linear precision in neither direction exactly, so only corners here).
  EXPECT_EQ(surface_point(s, 0.0, 0.0), Eigen::Vector3d(0, 0, 0));
  EXPECT_LT((surface_point(s, 1.0, 2.0) - Eigen::Vector3d(2, 4, -2)).norm(), 1e-15);
}

// The teapot's two PlaneSurfaces: bilinear, knots = the file's domains, corners = plane points at the
// extents (read field by field), all in the plane.
TEST(SurfaceObjects, PlaneSurfacesAreBilinearOverTheirExtents) {
  const std::string bytes = corpus_file("v5_teapot.3dm");
  const auto offsets = class_chunk_offsets(bytes, kPlaneSurfaceId);
  ASSERT_EQ(offsets.size(), 2u);
  for (const std::size_t at : offsets) {
    ArchiveReader raw = reader_at_class_data(bytes, "teapot", at);
    EXPECT_EQ(raw.u8(), 0x11);
    const Eigen::Vector3d origin = raw.point3(), x = raw.point3(), y = raw.point3(), z = raw.point3();
    raw.skip(4 * 8);
    const std::vector<double> domain = raw.doubles(4), extent = raw.doubles(4);
    ArchiveReader reader = reader_at_class_data(bytes, "teapot", at);
    const NurbsSurface s = read_plane_surface(reader);
    EXPECT_EQ(s.u_knots, (std::vector<double>{domain[0], domain[0], domain[1], domain[1]}));
    EXPECT_EQ(s.v_knots, (std::vector<double>{domain[2], domain[2], domain[3], domain[3]}));
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        EXPECT_EQ(s.point(i, j), origin + extent[i] * x + extent[2 + j] * y);
        EXPECT_NEAR((s.point(i, j) - origin).dot(z), 0.0, 1e-12);
      }
    const Eigen::Vector3d middle = origin + 0.5 * (extent[0] + extent[1]) * x + 0.5 * (extent[2] + extent[3]) * y;
    EXPECT_LT((surface_point(s, 0.5 * (domain[0] + domain[1]), 0.5 * (domain[2] + domain[3])) - middle).norm(), 1e-12);
  }
}

// The profile point p rotated by `angle` about the line (origin, unit z), right-handed (Rodrigues).
Eigen::Vector3d rotated(const Eigen::Vector3d& p, const Eigen::Vector3d& origin, const Eigen::Vector3d& z, double angle) {
  const Eigen::Vector3d v = p - origin;
  return origin + std::cos(angle) * v + std::sin(angle) * z.cross(v) + (1 - std::cos(angle)) * z.dot(v) * z;
}

// The teapot's six RevSurfaces: the NURBS is the profile revolved, point for point: at the revolution's
// own parameters (s, t), mapped to the NURBS's with revolution_nurbs_parameter, the surface point is
// profile(t) rotated by the angle of s; domains are the file's; a full turn closes exactly.
TEST(SurfaceObjects, RevSurfacesAreExactRevolutions) {
  const std::string bytes = corpus_file("v5_teapot.3dm");
  const auto offsets = class_chunk_offsets(bytes, kRevSurfaceId);
  ASSERT_EQ(offsets.size(), 6u);
  for (const std::size_t at : offsets) {
    ArchiveReader reader = reader_at_class_data(bytes, "teapot", at);
    const Revolution rev = read_revolution(reader);
    ArchiveReader again = reader_at_class_data(bytes, "teapot", at);
    const NurbsSurface s = read_rev_surface(again);
    const Eigen::Vector3d z = (rev.axis_to - rev.axis_from).normalized();
    const NurbsCurve& profile = rev.profile;
    const bool full = std::abs(rev.angle1 - rev.angle0 - 2 * std::numbers::pi) <= 1e-12;
    const double u0 = rev.transposed ? profile.domain_start() : rev.t0;
    const double u1 = rev.transposed ? profile.domain_end() : rev.t1;
    EXPECT_EQ(s.u_start(), u0);
    EXPECT_EQ(s.u_end(), u1);
    EXPECT_EQ(s.v_start(), rev.transposed ? rev.t0 : profile.domain_start());
    EXPECT_EQ(s.v_end(), rev.transposed ? rev.t1 : profile.domain_end());
    EXPECT_EQ((rev.transposed ? s.v_order : s.u_order), 3);
    for (int a = 0; a <= 12; ++a)
      for (int b = 0; b <= 8; ++b) {
        const double angle_param = rev.t0 + (rev.t1 - rev.t0) * a / 12.0;
        const double t = profile.domain_start() + (profile.domain_end() - profile.domain_start()) * b / 8.0;
        const double angle = rev.angle0 + (rev.angle1 - rev.angle0) * a / 12.0;
        const double nurbs_angle = revolution_nurbs_parameter(rev, angle_param);
        const Eigen::Vector3d got =
            rev.transposed ? surface_point(s, t, nurbs_angle) : surface_point(s, nurbs_angle, t);
        const Eigen::Vector3d expected = rotated(curve_point(profile, t), rev.axis_from, z, angle);
        EXPECT_LT((got - expected).norm(), 1e-12 * 200) << "rev at " << at << " a " << a << " b " << b;
        // Whatever the parameter, a point of a revolution keeps its profile point's distance from the axis.
        const Eigen::Vector3d any = rev.transposed ? surface_point(s, t, angle_param) : surface_point(s, angle_param, t);
        const Eigen::Vector3d p = curve_point(profile, t) - rev.axis_from;
        const Eigen::Vector3d q = any - rev.axis_from;
        EXPECT_NEAR((q - q.dot(z) * z).norm(), (p - p.dot(z) * z).norm(), 1e-12 * 200);
        EXPECT_NEAR(q.dot(z), p.dot(z), 1e-12 * 200);
      }
    if (full) {
      const int angle_count = rev.transposed ? s.v_count : s.u_count;
      const int profile_count = rev.transposed ? s.u_count : s.v_count;
      for (int j = 0; j < profile_count; ++j) {
        const auto first = rev.transposed ? s.point(j, 0) : s.point(0, j);
        const auto last = rev.transposed ? s.point(j, angle_count - 1) : s.point(angle_count - 1, j);
        EXPECT_EQ(first, last);
      }
    }
  }
}


// A cylinder as a transposed revolution of three quarters of a turn (4 spans, as openNURBS makes it);
// a sum of a rational arc and a line.
TEST(SurfaceObjects, SyntheticRevolutionAndSum) {
  Revolution rev;
  rev.profile = line({2, 0, 1}, {2, 0, 3}, 10, 12);
  rev.axis_from = {0, 0, 0};
  rev.axis_to = {0, 0, 5};
  rev.angle0 = 0.25;
  rev.angle1 = 0.25 + 1.5 * std::numbers::pi;
  rev.t0 = -1;
  rev.t1 = 1;
  rev.transposed = true;
  const NurbsSurface s = revolution_as_nurbs(rev);
  validate(s, "revolution");
  EXPECT_EQ(s.u_count, 2);
  EXPECT_EQ(s.v_count, 9);
  EXPECT_EQ(s.u_knots, rev.profile.knots);
  EXPECT_EQ(s.v_start(), -1.0);
  EXPECT_EQ(s.v_end(), 1.0);
  for (int k = 0; k <= 30; ++k) {
    const Eigen::Vector3d p = surface_point(s, 11.0, -1 + 2.0 * k / 30);
    EXPECT_NEAR(std::hypot(p.x(), p.y()), 2.0, 1e-14);
    EXPECT_NEAR(p.z(), 2.0, 1e-14);
  }
  EXPECT_LT((surface_point(s, 10, -1) - Eigen::Vector3d(2 * std::cos(0.25), 2 * std::sin(0.25), 1)).norm(), 1e-15);
  const double end = 0.25 + 1.5 * std::numbers::pi;
  EXPECT_LT((surface_point(s, 12, 1) - Eigen::Vector3d(2 * std::cos(end), 2 * std::sin(end), 3)).norm(), 1e-14);

  const NurbsCurve arc = arc_as_nurbs(CircularArc{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 3.0, 0.0, 2.0}, 0, 1, 3);
  const NurbsCurve v_line = line({0, 0, 0}, {0, 0, 4}, 5, 7);
  const Eigen::Vector3d base(1, 2, 3);
  const NurbsSurface sum = sum_as_nurbs(arc, v_line, base);
  validate(sum, "sum");
  for (int a = 0; a <= 10; ++a)
    for (int b = 0; b <= 4; ++b) {
      const double u = a / 10.0, v = 5 + b / 2.0;
      EXPECT_LT((surface_point(sum, u, v) - (base + curve_point(arc, u) + curve_point(v_line, v))).norm(), 1e-14);
    }
}



// ON_LineCurve class data: from, to, domain, dimension 3.
std::string line_object(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double t0, double t1) {
  ClassData d;
  d.put(std::uint8_t{0x10}).doubles({a.x(), a.y(), a.z(), b.x(), b.y(), b.z(), t0, t1}).put(3);
  return object_chunk("4ED7D4DB-E947-11D3-BFE5-0010830122F0", d.body);
}

// Hand-built ON_SumSurface and version-1 ON_RevSurface data (no corpus file has them): the nested curves
// are read through read_object, the sum's CVs are basepoint + P0_i + P1_j, the version-1 revolution's
// angle parameter is the angle itself.
TEST(SurfaceObjects, SumSurfaceAndVersionOneRevSurfaceData) {
  ClassData sum;
  sum.put(std::uint8_t{0x10}).doubles({10, 20, 30}).doubles({0, 0, 0, 0, 0, 0});
  const std::string sum_bytes =
      object_chunk("C4CD5359-446D-4690-9FF5-29059732472B", sum.body,
                   line_object({0, 0, 0}, {2, 0, 0}, 0, 1) + line_object({0, 0, 0}, {0, 3, 1}, 4, 5));
  ArchiveReader sum_reader(sum_bytes, "hand.3dm", 70);
  const NurbsSurface s = std::get<NurbsSurface>(read_object(sum_reader));
  EXPECT_EQ(s.u_knots, (std::vector<double>{0, 0, 1, 1}));
  EXPECT_EQ(s.v_knots, (std::vector<double>{4, 4, 5, 5}));
  EXPECT_EQ(s.point(1, 1), Eigen::Vector3d(12, 23, 31));
  EXPECT_EQ(s.point(1, 0), Eigen::Vector3d(12, 20, 30));
  EXPECT_EQ(sum_reader.offset(), sum_bytes.size());

  ClassData rev;  // axis z through the origin, half a turn from pi/2, not transposed, then the profile
  rev.put(std::uint8_t{0x10}).doubles({0, 0, 0, 0, 0, 1}).doubles({std::numbers::pi / 2, 1.5 * std::numbers::pi});
  rev.doubles({0, 0, 0, 0, 0, 0}).put(0).put(std::uint8_t{1});
  const std::string rev_bytes =
      object_chunk("A16220D3-163B-11D4-8000-0010830122F0", rev.body, line_object({1, 0, 0}, {1, 0, 2}, 0, 2));
  ArchiveReader rev_reader(rev_bytes, "hand.3dm", 70);
  const NurbsSurface r = std::get<NurbsSurface>(read_object(rev_reader));
  EXPECT_EQ(r.u_count, 5);  // two quarter spans
  EXPECT_EQ(r.u_start(), std::numbers::pi / 2);
  EXPECT_EQ(r.u_end(), 1.5 * std::numbers::pi);
  EXPECT_LT((surface_point(r, std::numbers::pi / 2, 0) - Eigen::Vector3d(0, 1, 0)).norm(), 1e-15);
  EXPECT_LT((surface_point(r, std::numbers::pi, 1) - Eigen::Vector3d(-1, 0, 1)).norm(), 1e-15);
  EXPECT_LT((surface_point(r, 1.5 * std::numbers::pi, 2) - Eigen::Vector3d(0, -1, 2)).norm(), 1e-15);
}

TEST(SurfaceObjects, RefusesBadSurfaces) {
  const std::string prefix = "hand.3dm: chunk 0x00027FFA at offset 0: ";
  // A rational bilinear surface with a negative weight.
  ClassData negative;
  negative.put(std::uint8_t{0x10}).put(3).put(1).put(2).put(2).put(2).put(2).put(0).put(0);
  negative.doubles({0, 0, 0, 0, 0, 0});
  negative.put(2).doubles({0, 1}).put(2).doubles({0, 1});
  negative.put(4).doubles({0, 0, 0, 1, 1, 0, 0, 1, 0, 1, 0, 1, 1, 1, 0, -1});
  EXPECT_EQ(error_of(negative.chunk(), read_nurbs_surface),
            prefix + "ON_NurbsSurface: weight of control point 3 is -1; weights must be positive");

  ClassData short_knots;
  short_knots.put(std::uint8_t{0x10}).put(3).put(0).put(2).put(2).put(2).put(3).put(0).put(0);
  short_knots.doubles({0, 0, 0, 0, 0, 0});
  short_knots.put(2).doubles({0, 1}).put(2).doubles({0, 1});
  EXPECT_EQ(error_of(short_knots.chunk(), read_nurbs_surface),
            prefix + "ON_NurbsSurface: 2 v knots stored, order 2 and 3 control points need 3");

  ClassData empty_plane;
  empty_plane.put(std::uint8_t{0x11}).doubles({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0});
  empty_plane.doubles({0, 1, 2, 2});
  EXPECT_EQ(error_of(empty_plane.chunk(), read_plane_surface),
            prefix + "ON_PlaneSurface: v domain [2, 2] does not increase");

  ClassData no_profile;  // RevSurface 2.0 without a curve
  no_profile.put(std::uint8_t{0x20}).doubles({0, 0, 0, 0, 0, 1, 0, 1, 0, 1, 0, 0, 0, 0, 0, 0}).put(0);
  no_profile.put(std::uint8_t{0});
  EXPECT_EQ(error_of(no_profile.chunk(), read_rev_surface), prefix + "ON_RevSurface: no profile curve");
}

}  // namespace
}  // namespace cadnurbs::rhino
