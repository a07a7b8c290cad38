#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "core/geometry_error.hpp"
#include "core/polygon_2d.hpp"
#include "formats/3dm/brep_object.hpp"
#include "formats/3dm/curve_objects.hpp"
#include "formats/3dm/flipped_face.hpp"
#include "formats/3dm/object_checks.hpp"
#include "formats/3dm/rhino_object.hpp"
#include "formats/3dm/typecodes.hpp"

// ON_Extrusion (opennurbs_beam.cpp): planar profile curves in the xy plane of a profile frame, swept along
// a line segment. Its class data is one anonymous chunk (version 1.x): the profile (one curve, or with
// several profiles an ON_PolyCurve whose segments are the profiles, outer first), the path line, the
// used part of the path m_t, the up vector, optional miter plane normals at both ends, the path's
// parameter domain, a transposed flag, and from 1.1 the profile count, from 1.2 the cap flags.
//
// The faces are those of openNURBS's ON_Extrusion::BrepForm, except that a profile is not split at its
// kinks: one side face per profile (profile x line, u along the profile, v along the path), then the
// bottom cap, then the top cap, as trimmed planes bounded by the profiles.

namespace cadnurbs::rhino {

namespace {

const Uuid kPolyCurveId = uuid_from_text("4ED7D4E0-E947-11D3-BFE5-0010830122F0");
const Uuid kOldPolyCurveId = uuid_from_text("EF638317-154B-11D4-8000-0010830122F0");

// The profiles: with several, the ON_PolyCurve's segments one by one (read_object would join them into
// one curve); with one, the curve as read_object converts it.
std::vector<NurbsCurve> read_profiles(ArchiveReader& reader, bool several) {
  if (several) {
    ArchiveReader probe = reader;  // looks at the class id without moving `reader`
    probe.begin_chunk(tcode::kOpennurbsClass);
    probe.begin_chunk(tcode::kOpennurbsClassUuid);
    const Uuid id = probe.uuid();
    if (id == kPolyCurveId || id == kOldPolyCurveId) {
      reader.begin_chunk(tcode::kOpennurbsClass);
      reader.begin_chunk(tcode::kOpennurbsClassUuid);
      reader.end_chunk();
      reader.begin_chunk(tcode::kOpennurbsClassData);
      reader.chunk_version();
      const int count = reader.i32();
      if (count < 1) reader.fail("Extrusion profile polycurve has " + std::to_string(count) + " segments");
      reader.i32();  // reserved
      reader.i32();
      reader.doubles(6);  // bounding box
      reader.doubles(reader.count(8));  // segment parameters: each profile keeps its own domain
      std::vector<NurbsCurve> out;
      for (int i = 0; i < count; ++i) out.push_back(nested_curve(reader, "ON_Extrusion", "profile " + std::to_string(i)));
      reader.end_chunk();
      reader.end_chunk();  // user data and the class end
      return out;
    }
  }
  return {nested_curve(reader, "ON_Extrusion", "profile")};
}

// ON_GetEndCapTransformation: the profile plane at one end of the path. Profile (x, y) goes to
// origin + x * x_axis + y * y_axis; with a miter normal N (relative to that plane) the profile is first
// stretched across the miter's tilt axis by 1/cos and then rotated about it into the miter plane, so that
// its projection along the path is the profile itself.
struct EndFrame {
  Eigen::Vector3d origin, x_axis, y_axis, z_axis;
  Eigen::Matrix2d stretch = Eigen::Matrix2d::Identity();  // the 2D profile -> the cap's 2D trims
  Eigen::Matrix3d tilt = Eigen::Matrix3d::Identity();     // the cap plane in frame coordinates
  Eigen::Vector3d cap_point(const Eigen::Vector2d& p) const {
    const Eigen::Vector3d q = tilt * Eigen::Vector3d(p.x(), p.y(), 0.0);
    return origin + q.x() * x_axis + q.y() * y_axis + q.z() * z_axis;
  }
  Eigen::Vector3d profile_point(const Eigen::Vector2d& p) const { return cap_point(stretch * p); }
};

EndFrame end_frame(const Eigen::Vector3d& origin, const Eigen::Vector3d& tangent, const Eigen::Vector3d& up,
                   bool have_normal, Eigen::Vector3d normal) {
  EndFrame f;
  f.origin = origin;
  f.z_axis = tangent.normalized();
  f.y_axis = up.normalized();
  f.x_axis = f.y_axis.cross(f.z_axis).normalized();
  constexpr double kMinNormalZ = 1.0 / 64.0;  // ON_Extrusion::m_Nz_min: steeper miters are ignored
  if (!have_normal || normal.norm() == 0.0) return f;
  normal.normalize();
  const Eigen::Vector3d axis(-normal.y(), normal.x(), 0.0);
  const double sin_a = axis.norm(), cos_a = normal.z();
  if (!(cos_a > kMinNormalZ) || sin_a == 0.0) return f;
  const Eigen::Vector3d a = axis / sin_a;
  const double c = 1.0 - 1.0 / cos_a;
  f.stretch << 1.0 - c * a.y() * a.y(), c * a.x() * a.y(), c * a.x() * a.y(), 1.0 - c * a.x() * a.x();
  f.tilt = Eigen::AngleAxisd(std::atan2(sin_a, cos_a), a).toRotationMatrix();
  return f;
}

// Signed area of the profile's control polygon is not the curve's; sample the curve instead.
double profile_signed_area(const NurbsCurve& profile) {
  std::vector<Eigen::Vector2d> points;
  const int n = 64 * std::max(1, profile.count());
  for (int i = 0; i < n; ++i) {
    const double t = profile.domain_start() + (profile.domain_end() - profile.domain_start()) * i / n;
    points.push_back(curve_point(profile, t).head<2>());
  }
  return polygon_signed_area(points);
}

bool is_closed(const NurbsCurve& c) {
  const Eigen::Vector3d a = curve_point(c, c.domain_start()), b = curve_point(c, c.domain_end());
  double size = 0;
  for (const auto& p : c.points) size = std::max(size, p.cwiseAbs().maxCoeff());
  return (a - b).norm() <= 1e-8 * std::max(size, 1.0);
}

Polyline2D line(Eigen::Vector2d a, Eigen::Vector2d b) { return Polyline2D{{a, b}}; }

// The profile as a 2D trimming curve with its points mapped by `m`.
NurbsCurve trim_curve(const NurbsCurve& profile, const Eigen::Matrix2d& m) {
  NurbsCurve c = profile;
  c.dimension = 2;
  for (auto& p : c.points) {
    const Eigen::Vector2d q = m * p.head<2>();
    p = Eigen::Vector3d(q.x(), q.y(), 0.0);
  }
  return c;
}

// A planar cap: the rectangle around the cap trims (grown by an eighth on each side, as openNURBS does,
// so that no trim runs along the plane's edge) as a bilinear NURBS mapped by `frame`, u = x, v = y.
NurbsSurface cap_plane(const std::vector<NurbsCurve>& trims, const EndFrame& frame) {
  Eigen::Vector2d lo = trims.front().points.front().head<2>(), hi = lo;
  for (const auto& c : trims)
    for (const auto& p : c.points) {
      lo = lo.cwiseMin(p.head<2>());
      hi = hi.cwiseMax(p.head<2>());
    }
  Eigen::Vector2d d = (hi - lo) / 8.0;
  for (int k = 0; k < 2; ++k)
    if (d[k] == 0.0) d[k] = 1.0;
  lo -= d;
  hi += d;
  NurbsSurface s;
  s.u_count = s.v_count = 2;
  s.u_knots = {lo.x(), lo.x(), hi.x(), hi.x()};
  s.v_knots = {lo.y(), lo.y(), hi.y(), hi.y()};
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) s.points.push_back(frame.cap_point({i ? hi.x() : lo.x(), j ? hi.y() : lo.y()}));
  return s;
}

}  // namespace

RhinoBrep read_extrusion(ArchiveReader& reader) {
  const auto [major, minor] = reader.begin_versioned_chunk(tcode::kAnonymousChunk);
  if (major != 1) reader.fail("Extrusion chunk version " + std::to_string(major) + " is unknown");
  // The profile comes before the profile count that says whether it holds several profiles; a
  // polycurve profile of an extrusion written as 1.1+ with count > 1 is split, so look ahead for it.
  // Profiles are read after the fixed fields are known: read the fields from a copy first.
  ArchiveReader ahead = reader;
  ahead.skip(ahead.peek_chunk().body_end - ahead.offset());
  ahead.point3();
  ahead.point3();
  ahead.doubles(2);
  ahead.point3();
  ahead.boolean();
  ahead.boolean();
  ahead.point3();
  ahead.point3();
  ahead.doubles(2);
  ahead.boolean();
  const int profile_count = minor >= 1 ? ahead.i32() : 1;
  if (profile_count < 1) reader.fail("Extrusion has " + std::to_string(profile_count) + " profiles");

  std::vector<NurbsCurve> profiles = read_profiles(reader, profile_count > 1);
  // Clamped, and a closed profile closed exactly, so that caps' loops close and seams meet.
  for (auto& profile : profiles) {
    profile = clamped(profile);
    if (is_closed(profile)) profile.points.back() = profile.points.front();
  }
  if (static_cast<int>(profiles.size()) != profile_count)
    reader.fail("Extrusion says " + std::to_string(profile_count) + " profiles, its profile holds " +
                std::to_string(profiles.size()));
  const Eigen::Vector3d from = reader.point3(), to = reader.point3();
  const std::vector<double> used = reader.doubles(2);  // the part of the path line swept, in [0, 1]
  const Eigen::Vector3d up = reader.point3();
  const bool have_normal0 = reader.boolean(), have_normal1 = reader.boolean();
  const Eigen::Vector3d normal0 = reader.point3(), normal1 = reader.point3();
  const std::vector<double> path_domain = reader.doubles(2);
  const bool transposed = reader.boolean();
  if (minor >= 1) reader.i32();
  bool cap0 = false, cap1 = false;
  if (minor >= 2) {
    cap0 = reader.boolean();
    cap1 = reader.boolean();
  } else {
    cap0 = cap1 = is_closed(profiles.front());
  }
  reader.end_chunk();  // the mesh cache (1.3) is not needed

  const Eigen::Vector3d tangent = to - from;
  if (!(tangent.norm() > 0) || !(up.norm() > 0) || !(path_domain[0] < path_domain[1]))
    reader.fail("Extrusion has a degenerate path or up vector");
  const EndFrame end0 = end_frame(from + used[0] * tangent, tangent, up, have_normal0, normal0);
  const EndFrame end1 = end_frame(from + used[1] * tangent, tangent, up, have_normal1, normal1);

  // Caps need closed profiles, the outer one counter-clockwise and the others clockwise (openNURBS
  // leaves an extrusion with other profiles uncapped).
  bool capped = cap0 || cap1;
  for (std::size_t p = 0; p < profiles.size() && capped; ++p)
    capped = is_closed(profiles[p]) && (profile_signed_area(profiles[p]) > 0) == (p == 0);
  cap0 = cap0 && capped;
  cap1 = cap1 && capped;

  RhinoBrep brep;
  // Edges per profile p: bottom (along the profile at the path's start), top, and the side edges: the
  // seam of a closed profile, or the lines at an open profile's start and end (all running from bottom
  // to top).
  struct ProfileEdges {
    int bottom, top, start_side, end_side;
  };
  std::vector<ProfileEdges> edges;
  for (const auto& profile : profiles) {
    ProfileEdges e;
    e.bottom = brep.edge_count++;
    e.top = brep.edge_count++;
    e.start_side = brep.edge_count++;
    e.end_side = is_closed(profile) ? e.start_side : brep.edge_count++;
    edges.push_back(e);
  }

  brep.edge_tolerances.assign(brep.edge_count, 0.0);  // built exact

  for (std::size_t p = 0; p < profiles.size(); ++p) {
    const NurbsCurve& profile = profiles[p];
    TrimmedSurface side;
    NurbsSurface& s = side.surface;
    s.u_order = profile.order;
    s.v_order = 2;
    s.u_count = profile.count();
    s.v_count = 2;
    s.u_knots = profile.knots;
    s.v_knots = {path_domain[0], path_domain[0], path_domain[1], path_domain[1]};
    for (const EndFrame* end : {&end0, &end1})
      for (const auto& q : profile.points) s.points.push_back(end->profile_point(q.head<2>()));
    if (profile.is_rational()) {
      s.weights = profile.weights;
      s.weights.insert(s.weights.end(), profile.weights.begin(), profile.weights.end());
    }
    const double a = profile.domain_start(), b = profile.domain_end();
    const double v0 = path_domain[0], v1 = path_domain[1];
    TrimLoop loop;
    loop.segments = {line({a, v0}, {b, v0}), line({b, v0}, {b, v1}), line({b, v1}, {a, v1}), line({a, v1}, {a, v0})};
    loop.edges = {{edges[p].bottom, false}, {edges[p].end_side, false}, {edges[p].top, true}, {edges[p].start_side, true}};
    side.loops.push_back(std::move(loop));
    brep.faces.push_back(std::move(side));
  }

  // Caps: the plane's normal is the path's direction, right for the top cap; the bottom one is flipped.
  for (int end = 0; end < 2; ++end) {
    if (!(end == 0 ? cap0 : cap1)) continue;
    const EndFrame& frame = end == 0 ? end0 : end1;
    std::vector<NurbsCurve> trims;
    for (const auto& profile : profiles) trims.push_back(trim_curve(profile, frame.stretch));
    TrimmedSurface cap;
    cap.surface = cap_plane(trims, frame);
    for (std::size_t p = 0; p < trims.size(); ++p) {
      TrimLoop loop;
      loop.segments.emplace_back(std::move(trims[p]));
      loop.edges.push_back({end == 0 ? edges[p].bottom : edges[p].top, false});
      cap.loops.push_back(std::move(loop));
    }
    brep.faces.push_back(end == 0 ? flipped(cap) : std::move(cap));
  }

  // A transposed extrusion is the same shape with its parameters swapped, which turns every normal round
  // (openNURBS marks such a capped extrusion a solid with inward normals).
  if (transposed)
    for (auto& face : brep.faces) face = flipped(face);

  for (std::size_t fi = 0; fi < brep.faces.size(); ++fi) {
    try {
      validate(brep.faces[fi], "extrusion face " + std::to_string(fi), 1e-9);
    } catch (const GeometryError& e) {
      reader.fail(e.what());
    }
  }
  for (std::size_t k = 0; k < brep.faces.size(); ++k) brep.face_indices.push_back(static_cast<int>(k));
  return brep;
}

}  // namespace cadnurbs::rhino
