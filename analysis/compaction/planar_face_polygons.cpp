#include "analysis/compaction/planar_face_polygons.hpp"

#include <cmath>

#include "analysis/compaction/join_straight_trim_runs.hpp"
#include "analysis/compaction/merge_convex_polygons.hpp"
#include "analysis/mesh/triangulate_polygon.hpp"
#include "core/polygon_2d.hpp"

namespace cadnurbs {

namespace {

// One bilinear patch (order 2 x 2, 2 x 2 control points) whose weights, if any, are all equal: a
// polynomial bilinear map, the only kind the two tests below accept.
bool polynomial_bilinear(const NurbsSurface& s) {
  if (s.u_order != 2 || s.v_order != 2 || s.u_count != 2 || s.v_count != 2) return false;
  if (s.is_rational())
    for (double w : s.weights)
      if (std::abs(w - s.weights[0]) > 1e-12 * s.weights[0]) return false;
  return true;
}

bool affine_surface(const NurbsSurface& s, double tolerance) {
  // Bilinear with P00 + P11 = P10 + P01 is affine.
  return polynomial_bilinear(s) && (s.point(0, 0) + s.point(1, 1) - s.point(1, 0) - s.point(0, 1)).norm() <= tolerance;
}

// Counter-clockwise and convex: no corner turns right by more than `tolerance` off the straight line.
bool convex(const std::vector<Eigen::Vector2d>& polygon, double tolerance) {
  const size_t n = polygon.size();
  for (size_t i = 0; i < n; ++i)
    if (!convex_corner(polygon[(i + n - 1) % n], polygon[i], polygon[(i + 1) % n], tolerance)) return false;
  return true;
}

// A bilinear patch whose four corners lie in one plane (within `tolerance`): planar, but not an affine
// map when it is no parallelogram, so only its iso-lines are straight in 3D.
bool planar_bilinear(const NurbsSurface& s, double tolerance) {
  if (!polynomial_bilinear(s)) return false;
  const Eigen::Vector3d normal = (s.point(1, 0) - s.point(0, 0)).cross(s.point(0, 1) - s.point(0, 0));
  if (normal.norm() == 0.0) return false;
  return std::abs(normal.normalized().dot(s.point(1, 1) - s.point(0, 0))) <= tolerance;
}

// Every edge of the polygon runs along u or along v.
bool along_iso_lines(const std::vector<Eigen::Vector2d>& polygon, double tolerance) {
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d d = polygon[(i + 1) % polygon.size()] - polygon[i];
    if (std::abs(d.x()) > tolerance && std::abs(d.y()) > tolerance) return false;
  }
  return true;
}

// The corners of the loops in (u,v), each a closed polygon without repeated points; nothing when a
// segment is not straight or a loop bounds no area.
std::optional<std::vector<std::vector<Eigen::Vector2d>>> straight_loops(const TrimmedSurface& face,
                                                                        double uv_tolerance) {
  const NurbsSurface& s = face.surface;
  std::vector<std::vector<Eigen::Vector2d>> loops;
  if (face.loops.empty())
    loops.push_back({{s.u_start(), s.v_start()}, {s.u_end(), s.v_start()}, {s.u_end(), s.v_end()}, {s.u_start(), s.v_end()}});
  for (const auto& loop : face.loops) {
    std::vector<Eigen::Vector2d> polygon;
    for (const auto& segment : loop.segments) {
      const auto points = straight_segment_points(segment, uv_tolerance);
      if (!points) return std::nullopt;
      for (const auto& p : *points)
        if (polygon.empty() || (p - polygon.back()).norm() > uv_tolerance) polygon.push_back(p);
    }
    while (polygon.size() > 1 && (polygon.front() - polygon.back()).norm() <= uv_tolerance) polygon.pop_back();
    if (polygon.size() < 3 || std::abs(polygon_signed_area(polygon)) <= uv_tolerance * uv_tolerance) return std::nullopt;
    loops.push_back(std::move(polygon));
  }
  return loops;
}

}  // namespace

std::optional<PolygonMesh> planar_face_polygons(const TrimmedSurface& face, double tolerance) {
  const NurbsSurface& s = face.surface;
  const bool affine = affine_surface(s, tolerance);
  if (!affine && !planar_bilinear(s, tolerance)) return std::nullopt;
  const double uv_tolerance = trim_parameter_tolerance(s, tolerance);
  auto loops = straight_loops(face, uv_tolerance);
  if (!loops) return std::nullopt;
  auto to_3d = [&](const Eigen::Vector2d& p) -> Eigen::Vector3d { return surface_point(s, p.x(), p.y()); };

  PolygonMesh mesh;
  if (loops->size() == 1) {
    std::vector<Eigen::Vector2d> polygon = (*loops)[0];
    if (polygon_signed_area(polygon) < 0) std::reverse(polygon.begin(), polygon.end());
    // A non-affine patch maps only iso-lines to straight lines, and one convex piece to one.
    const bool exact = affine || along_iso_lines(polygon, uv_tolerance);
    if (exact && convex(polygon, uv_tolerance)) {
      std::vector<int> corners;
      for (const auto& p : polygon) {
        corners.push_back(static_cast<int>(mesh.positions.size()));
        mesh.positions.push_back(to_3d(p));
      }
      mesh.polygons.push_back(std::move(corners));
      return mesh;
    }
  }
  if (!affine) return std::nullopt;  // cut diagonals would bend
  PlanarTriangulation triangulation;
  try {
    triangulation = triangulate_polygon(*loops);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (triangulation.triangles.empty()) return std::nullopt;
  for (const auto& p : triangulation.points) mesh.positions.push_back(to_3d(p));
  mesh.polygons = merge_convex_polygons(triangulation.points, triangulation.triangles, uv_tolerance);
  return mesh;
}

}  // namespace cadnurbs
