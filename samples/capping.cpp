#include "samples/capping.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "analysis/mesh/triangulate_polygon.hpp"
#include "core/geometry_error.hpp"

namespace cadnurbs {

namespace {

// Whole profile, counter-clockwise in (x, z) so that the body's normals Su x Sv point outward:
// the half profile backwards (bottom -> +x side -> top), then its mirror (top -> -x side -> bottom).
Outline full_profile(const Outline& half) {
  Outline out;
  for (auto it = half.segments.rbegin(); it != half.segments.rend(); ++it) {
    OutlineSegment s = *it;
    std::swap(s.start, s.end);
    s.sweep = -s.sweep;  // traversed backwards
    out.segments.push_back(s);
  }
  for (OutlineSegment s : half.segments) {
    s.start.x() = -s.start.x();
    s.end.x() = -s.end.x();
    s.centre.x() = -s.centre.x();
    s.sweep = -s.sweep;  // mirrored
    out.segments.push_back(s);
  }
  return out;
}

// 3D frame of the path plane: where a path point (a, b) goes, and the two profile axes for a
// path-plane left normal n.
struct PathFrame {
  bool vertical;  // plane xz
  Eigen::Vector3d point(const Eigen::Vector2d& p) const {
    return vertical ? Eigen::Vector3d(p.x(), 0, p.y()) : Eigen::Vector3d(p.x(), p.y(), 0);
  }
  Eigen::Vector3d in_plane(const Eigen::Vector2d& n) const {
    return vertical ? Eigen::Vector3d(n.x(), 0, n.y()) : Eigen::Vector3d(n.x(), n.y(), 0);
  }
  // Profile x axis and z axis for left normal n (not necessarily unit: exact offsets at arc middles).
  // (x_axis, z_axis, tangent) is right-handed in both planes, so normals point outward in both.
  Eigen::Vector3d x_axis(const Eigen::Vector2d& n) const { return vertical ? Eigen::Vector3d(0, 1, 0) : in_plane(n); }
  Eigen::Vector3d z_axis(const Eigen::Vector2d& n) const { return vertical ? in_plane(n) : Eigen::Vector3d(0, 0, 1); }
};

// A planar lid in the profile plane at a path end, trimmed by the whole profile.
TrimmedSurface make_lid(const NurbsCurve& profile, const Eigen::Vector3d& origin, const Eigen::Vector3d& x_axis,
                        const Eigen::Vector3d& z_axis, bool at_start) {
  double xmin = std::numeric_limits<double>::max(), xmax = -xmin, zmin = xmin, zmax = -xmin;
  for (const auto& p : profile.points) {
    xmin = std::min(xmin, p.x());
    xmax = std::max(xmax, p.x());
    zmin = std::min(zmin, p.y());
    zmax = std::max(zmax, p.y());
  }
  // A margin keeps the trimming loop strictly inside the domain.
  const double mx = 0.02 * (xmax - xmin), mz = 0.02 * (zmax - zmin);
  xmin -= mx, xmax += mx, zmin -= mz, zmax += mz;
  // u runs along one profile axis, v along the other, ordered so that Su x Sv points out of the body.
  const Eigen::Vector3d u_axis = at_start ? z_axis : x_axis, v_axis = at_start ? x_axis : z_axis;
  const double u0 = at_start ? zmin : xmin, u1 = at_start ? zmax : xmax;
  const double v0 = at_start ? xmin : zmin, v1 = at_start ? xmax : zmax;
  TrimmedSurface lid;
  NurbsSurface& s = lid.surface;
  s.u_order = s.v_order = 2;
  s.u_count = s.v_count = 2;
  s.u_knots = s.v_knots = {0, 0, 1, 1};
  for (double v : {v0, v1})
    for (double u : {u0, u1}) s.points.push_back(origin + u * u_axis + v * v_axis);
  // The profile in the lid's (u, v): an affine map of its (x, z), so the rational curve stays exact.
  NurbsCurve loop = profile;
  for (auto& p : loop.points) {
    const double x = p.x(), z = p.y();
    const double pu = at_start ? z : x, pv = at_start ? x : z;
    p = Eigen::Vector3d((pu - u0) / (u1 - u0), (pv - v0) / (v1 - v0), 0.0);
  }
  TrimLoop trim;
  trim.segments.emplace_back(loop);
  if (loop_signed_area(trim) < 0) trim = reversed(trim);
  lid.loops.push_back(std::move(trim));
  return lid;
}

}  // namespace

CappingDefinition parse_capping(const std::string& name, const std::string& path_text, const std::string& path_name,
                                const std::string& profile_text, const std::string& profile_name) {
  CappingDefinition c;
  c.name = name;
  c.path = parse_outline(path_text, path_name);
  require_smooth(c.path, path_name);
  c.half_profile = parse_outline(profile_text, profile_name);
  const auto& segs = c.half_profile.segments;
  if (std::abs(segs.front().start.x()) > 1e-12 || std::abs(segs.back().end.x()) > 1e-12)
    throw std::runtime_error(profile_name + ": a half profile must start and end on the axis x = 0");
  if (segs.front().start.y() <= segs.back().end.y())
    throw std::runtime_error(profile_name + ": a half profile must start at the top and end at the bottom");
  for (size_t i = 0; i < segs.size(); ++i) {
    Outline one;
    one.segments = {segs[i]};
    for (const auto& p : sample_outline(one, 1e-3 * segs[i].radius + 1e-9))
      if (p.point.x() < -1e-9)
        throw std::runtime_error(profile_name + ": segment " + std::to_string(i + 1) + " crosses the axis x = 0");
  }
  return c;
}

Scene capping_nurbs(const CappingDefinition& capping) {
  const PathFrame frame{capping.path.plane == "xz"};
  const NurbsCurve path = outline_to_nurbs(capping.path);
  const std::vector<Eigen::Vector2d> normals = outline_offset_normals(capping.path);
  const NurbsCurve profile = outline_to_nurbs(full_profile(capping.half_profile));

  TrimmedSurface body;
  NurbsSurface& s = body.surface;
  s.u_order = profile.order;
  s.v_order = path.order;
  s.u_count = profile.count();
  s.v_count = path.count();
  s.u_knots = profile.knots;
  s.v_knots = path.knots;
  for (int j = 0; j < path.count(); ++j)
    for (int i = 0; i < profile.count(); ++i) {
      const Eigen::Vector2d n = normals[j];
      s.points.push_back(frame.point(path.points[j].head<2>()) + profile.points[i].x() * frame.x_axis(n) +
                         profile.points[i].y() * frame.z_axis(n));
      s.weights.push_back(profile.weights[i] * path.weights[j]);
    }

  const auto& first = capping.path.segments.front();
  const auto& last = capping.path.segments.back();
  const Eigen::Vector2d n0 = normals.front(), n1 = normals.back();
  TrimmedSurface lid_start = make_lid(profile, frame.point(first.start), frame.x_axis(n0), frame.z_axis(n0), true);
  TrimmedSurface lid_end = make_lid(profile, frame.point(last.end), frame.x_axis(n1), frame.z_axis(n1), false);

  Scene scene;
  scene.root.name = capping.name;
  scene.root.colour = Colour{0.72, 0.52, 0.32};  // oak
  scene.root.shapes.push_back({"body", body, std::nullopt});
  scene.root.shapes.push_back({"lid-start", lid_start, std::nullopt});
  scene.root.shapes.push_back({"lid-end", lid_end, std::nullopt});
  validate(scene);
  return scene;
}

TriangleMesh capping_mesh(const CappingDefinition& capping, double max_chord_deviation, bool with_lids) {
  const PathFrame frame{capping.path.plane == "xz"};
  auto ring = sample_outline(full_profile(capping.half_profile), max_chord_deviation);
  // The path's arcs carry the profile out to its half width, where the same angle makes a
  // longer chord: divide them for the outermost circle, so the bound holds on the whole surface.
  double reach = 0;  // largest offset along the path plane's normal
  for (const auto& rs : ring) reach = std::max(reach, std::abs(frame.vertical ? rs.point.y() : rs.point.x()));
  const auto path = sample_outline(capping.path, max_chord_deviation, reach);
  ring.pop_back();  // closed: the last point repeats the first
  const int m = static_cast<int>(ring.size());

  TriangleMesh mesh;
  for (const auto& ps : path)
    for (const auto& rs : ring)
      mesh.positions.push_back(frame.point(ps.point) + rs.point.x() * frame.x_axis(ps.left_normal) +
                               rs.point.y() * frame.z_axis(ps.left_normal));
  for (int j = 0; j + 1 < static_cast<int>(path.size()); ++j)
    for (int i = 0; i < m; ++i) {
      const int a = j * m + i, b = j * m + (i + 1) % m, c = (j + 1) * m + (i + 1) % m, d = (j + 1) * m + i;
      mesh.triangles.push_back({a, b, c});
      mesh.triangles.push_back({a, c, d});
    }
  if (!with_lids) return mesh;
  // Lids: the ring polygon triangulated in the profile plane, oriented outward.
  std::vector<Eigen::Vector2d> polygon;
  for (const auto& rs : ring) polygon.push_back(rs.point);
  const auto lid = triangulate_polygon({polygon}).triangles;
  const int last_ring = (static_cast<int>(path.size()) - 1) * m;
  for (const auto& t : lid) {
    // The ring is counter-clockwise in (x, z) and x_axis x z_axis is the path tangent: the end lid
    // keeps that order (normal along the tangent), the start lid reverses it.
    mesh.triangles.push_back({t[0], t[2], t[1]});
    mesh.triangles.push_back({last_ring + t[0], last_ring + t[1], last_ring + t[2]});
  }
  return mesh;
}

double distance_to_swept_surface(const CappingDefinition& capping, const Eigen::Vector3d& point) {
  const bool vertical = capping.path.plane == "xz";
  // The point in the path plane, and its coordinate across it.
  const Eigen::Vector2d q = vertical ? Eigen::Vector2d(point.x(), point.z()) : point.head<2>();
  const double across = vertical ? point.y() : point.z();
  double best = std::numeric_limits<double>::max();
  const Outline profile = full_profile(capping.half_profile);
  for (const auto& seg : capping.path.segments) {
    // Nearest path point: foot of the perpendicular on a line, radial projection on an arc.
    double offset;  // signed distance along the left normal
    bool inside;
    if (!seg.is_arc) {
      const Eigen::Vector2d t = (seg.end - seg.start).normalized();
      const double s = (q - seg.start).dot(t);
      inside = s >= -1e-9 && s <= (seg.end - seg.start).norm() + 1e-9;
      offset = (q - seg.start).dot(Eigen::Vector2d(-t.y(), t.x()));
    } else {
      const Eigen::Vector2d r = q - seg.centre;
      inside = angle_along_arc(seg, q) <= std::abs(seg.sweep) + 1e-9;
      offset = (seg.sweep > 0 ? 1.0 : -1.0) * (seg.radius - r.norm());
    }
    if (!inside) continue;
    // Profile coordinates of the point in this cross-section.
    const Eigen::Vector2d xz = vertical ? Eigen::Vector2d(across, offset) : Eigen::Vector2d(offset, across);
    for (const auto& ps : profile.segments) best = std::min(best, distance_to_segment(ps, xz));
  }
  return best;
}

}  // namespace cadnurbs
