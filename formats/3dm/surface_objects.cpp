#include "formats/3dm/surface_objects.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "core/number_format.hpp"
#include "formats/3dm/curve_objects.hpp"
#include "formats/3dm/object_checks.hpp"

namespace cadnurbs::rhino {

namespace {

// openNURBS's ON_ZERO_TOLERANCE: its pole test (a profile end this close to the axis is on it).
constexpr double kZeroTolerance = 1.0e-12;

}  // namespace

NurbsSurface transposed(const NurbsSurface& s) {
  NurbsSurface t;
  t.u_order = s.v_order;
  t.v_order = s.u_order;
  t.u_count = s.v_count;
  t.v_count = s.u_count;
  t.u_knots = s.v_knots;
  t.v_knots = s.u_knots;
  t.points.resize(s.points.size());
  if (s.is_rational()) t.weights.resize(s.points.size());
  for (int i = 0; i < s.u_count; ++i)
    for (int j = 0; j < s.v_count; ++j) {
      t.points[t.index(j, i)] = s.point(i, j);
      if (s.is_rational()) t.weights[t.index(j, i)] = s.weight(i, j);
    }
  return t;
}

NurbsSurface read_nurbs_surface(ArchiveReader& reader) {
  constexpr const char* kClass = "ON_NurbsSurface";
  expect_major_version(reader, kClass, 1);
  const int dimension = reader.i32();
  const bool rational = reader.i32() != 0;
  const int order[2] = {reader.i32(), reader.i32()};
  const int cv_count[2] = {reader.i32(), reader.i32()};
  reader.skip(2 * 4 + 6 * 8);  // two reserved ints, a bounding box written empty
  expect_dimension(reader, kClass, dimension);
  expect_order_and_count(reader, kClass, "u", order[0], cv_count[0]);
  expect_order_and_count(reader, kClass, "v", order[1], cv_count[1]);
  const std::vector<double> u_knots = read_knots(reader, kClass, "u", order[0], cv_count[0]);
  const std::vector<double> v_knots = read_knots(reader, kClass, "v", order[1], cv_count[1]);
  const std::size_t stored =
      read_count(reader, kClass, 8 * static_cast<std::size_t>(dimension + (rational ? 1 : 0)), "control points");
  if (static_cast<std::int64_t>(stored) != std::int64_t{cv_count[0]} * cv_count[1])
    refuse(reader, kClass, std::to_string(stored) + " control points stored, the header says " +
                               std::to_string(cv_count[0]) + " x " + std::to_string(cv_count[1]));
  // The file's CV(i, j) comes at i * v_count + j, v fastest: read as the surface with u and v swapped
  // (whose u is fastest), then swapped back.
  NurbsSurface swapped;
  swapped.u_order = order[1];
  swapped.v_order = order[0];
  swapped.u_count = cv_count[1];
  swapped.v_count = cv_count[0];
  swapped.u_knots = v_knots;
  swapped.v_knots = u_knots;
  read_control_points(reader, kClass, dimension, rational, stored, swapped.points, swapped.weights);
  return checked(reader, kClass, transposed(swapped));
}

NurbsSurface read_plane_surface(ArchiveReader& reader) {
  constexpr const char* kClass = "ON_PlaneSurface";
  const int minor = expect_major_version(reader, kClass, 1);
  const Eigen::Vector3d origin = reader.point3();
  const Eigen::Vector3d x_axis = reader.point3();
  const Eigen::Vector3d y_axis = reader.point3();
  reader.skip(3 * 8 + 4 * 8);  // z axis and plane equation: implied by the others
  const auto domain_u = read_increasing_interval(reader, kClass, "u domain");
  const auto domain_v = read_increasing_interval(reader, kClass, "v domain");
  // Chunk 1.0 had no extents: the domain was the extent.
  const auto extent_u = minor >= 1 ? read_increasing_interval(reader, kClass, "u extent") : domain_u;
  const auto extent_v = minor >= 1 ? read_increasing_interval(reader, kClass, "v extent") : domain_v;
  NurbsSurface s;
  s.u_count = s.v_count = 2;
  s.u_knots = {domain_u.first, domain_u.first, domain_u.second, domain_u.second};
  s.v_knots = {domain_v.first, domain_v.first, domain_v.second, domain_v.second};
  const double eu[2] = {extent_u.first, extent_u.second};
  const double ev[2] = {extent_v.first, extent_v.second};
  s.points.resize(4);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) s.points[s.index(i, j)] = origin + eu[i] * x_axis + ev[j] * y_axis;
  return checked(reader, kClass, std::move(s));
}

Revolution read_revolution(ArchiveReader& reader) {
  constexpr const char* kClass = "ON_RevSurface";
  const auto [major, minor] = reader.chunk_version();
  if (major != 1 && major != 2)
    refuse(reader, kClass,
           "chunk version " + std::to_string(major) + "." + std::to_string(minor) + " (only 1.x and 2.x are read)");
  Revolution rev;
  rev.axis_from = reader.point3();
  rev.axis_to = reader.point3();
  const auto angle = read_increasing_interval(reader, kClass, "angle interval");
  rev.angle0 = angle.first;
  rev.angle1 = angle.second;
  // Version 1 had no angle domain: the parameter was the angle itself.
  const auto domain = major == 2 ? read_increasing_interval(reader, kClass, "angle domain") : angle;
  rev.t0 = domain.first;
  rev.t1 = domain.second;
  reader.skip(6 * 8);  // bounding box
  rev.transposed = reader.i32() != 0;
  if (reader.u8() == 0) refuse(reader, kClass, "no profile curve");
  if (!((rev.axis_to - rev.axis_from).norm() > 0.0)) refuse(reader, kClass, "the axis has zero length");
  if (rev.angle1 - rev.angle0 > 2.0 * std::numbers::pi + kZeroTolerance)
    refuse(reader, kClass,
           "angle interval [" + number_text(rev.angle0, 17) + ", " + number_text(rev.angle1, 17) +
               "] exceeds a full turn");
  rev.profile = nested_curve(reader, kClass, "the profile");
  return rev;
}

NurbsSurface revolution_as_nurbs(const Revolution& rev) {
  CircularArc unit;
  unit.angle0 = rev.angle0;
  unit.angle1 = rev.angle1;
  const NurbsCurve arc = arc_as_nurbs(unit, rev.t0, rev.t1, 3);
  const NurbsCurve& profile = rev.profile;
  const Eigen::Vector3d origin = rev.axis_from;
  const Eigen::Vector3d z = (rev.axis_to - rev.axis_from).normalized();

  // u is the angle, v the profile; swapped at the end when the revolution is transposed.
  const int arc_count = arc.count(), profile_count = profile.count();
  std::vector<Eigen::Vector3d> points(static_cast<std::size_t>(arc_count) * profile_count);
  std::vector<double> weights(points.size());
  for (int j = 0; j < profile_count; ++j) {
    const Eigen::Vector3d c = profile.points[j] - origin;
    const double height = c.dot(z);
    Eigen::Vector3d radial = c - height * z;
    if (radial.norm() <= kZeroTolerance) radial.setZero();  // a pole stays on the axis
    const Eigen::Vector3d tangential = z.cross(radial);
    for (int k = 0; k < arc_count; ++k) {
      // Arc CV k = radius factor * (cos, sin) of its angle: the profile CV rotated and pushed out alike.
      const Eigen::Vector3d& a = arc.points[k];
      points[k + static_cast<std::size_t>(j) * arc_count] = origin + height * z + a.x() * radial + a.y() * tangential;
      weights[k + static_cast<std::size_t>(j) * arc_count] = arc.weights[k] * profile.weight(j);
    }
  }
  NurbsSurface s;
  s.u_order = arc.order;
  s.v_order = profile.order;
  s.u_count = arc_count;
  s.v_count = profile_count;
  s.u_knots = arc.knots;
  s.v_knots = profile.knots;
  s.points = std::move(points);
  s.weights = std::move(weights);
  return rev.transposed ? transposed(s) : s;
}

double revolution_nurbs_parameter(const Revolution& rev, double s) {
  CircularArc unit;
  unit.angle0 = rev.angle0;
  unit.angle1 = rev.angle1;
  return arc_nurbs_parameter(unit, rev.t0, rev.t1, s);
}

NurbsSurface read_rev_surface(ArchiveReader& reader) {
  return checked(reader, "ON_RevSurface", revolution_as_nurbs(read_revolution(reader)));
}

NurbsSurface read_sum_surface(ArchiveReader& reader) {
  constexpr const char* kClass = "ON_SumSurface";
  expect_major_version(reader, kClass, 1);
  const Eigen::Vector3d basepoint = reader.point3();
  reader.skip(6 * 8);  // bounding box
  const NurbsCurve u_curve = nested_curve(reader, kClass, "curve 0");
  const NurbsCurve v_curve = nested_curve(reader, kClass, "curve 1");
  return checked(reader, kClass, sum_as_nurbs(u_curve, v_curve, basepoint));
}

NurbsSurface sum_as_nurbs(const NurbsCurve& u_curve, const NurbsCurve& v_curve, const Eigen::Vector3d& basepoint) {
  NurbsSurface s;
  s.u_order = u_curve.order;
  s.v_order = v_curve.order;
  s.u_count = u_curve.count();
  s.v_count = v_curve.count();
  s.u_knots = u_curve.knots;
  s.v_knots = v_curve.knots;
  const bool rational = u_curve.is_rational() || v_curve.is_rational();
  s.points.resize(static_cast<std::size_t>(s.u_count) * s.v_count);
  if (rational) s.weights.resize(s.points.size());
  for (int j = 0; j < s.v_count; ++j)
    for (int i = 0; i < s.u_count; ++i) {
      s.points[s.index(i, j)] = basepoint + u_curve.points[i] + v_curve.points[j];
      if (rational) s.weights[s.index(i, j)] = u_curve.weight(i) * v_curve.weight(j);
    }
  return s;
}

}  // namespace cadnurbs::rhino
