#include "core/planar_polygon_surface.hpp"

#include <Eigen/Geometry>

namespace cadnurbs {

std::optional<TrimmedSurface> planar_polygon_surface(const std::vector<Eigen::Vector3d>& corners) {
  const size_t n = corners.size();
  if (n < 3) return std::nullopt;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // Newell: twice the area vector
  size_t longest = 0;
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d& a = corners[i];
    const Eigen::Vector3d& b = corners[(i + 1) % n];
    normal += a.cross(b);
    if ((b - a).squaredNorm() > (corners[(longest + 1) % n] - corners[longest]).squaredNorm()) longest = i;
  }
  if (!(normal.norm() > 0)) return std::nullopt;
  normal.normalize();
  const Eigen::Vector3d& origin = corners[0];
  Eigen::Vector3d e1 = corners[(longest + 1) % n] - corners[longest];
  e1 = (e1 - e1.dot(normal) * normal).normalized();
  const Eigen::Vector3d e2 = normal.cross(e1);

  std::vector<Eigen::Vector2d> uv(n);
  Eigen::AlignedBox2d box;
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d d = corners[i] - origin;
    uv[i] = {d.dot(e1), d.dot(e2)};
    box.extend(uv[i]);
  }
  if (!(box.sizes().minCoeff() > 0)) return std::nullopt;

  TrimmedSurface face;
  NurbsSurface& s = face.surface;
  s.u_order = s.v_order = 2;
  s.u_count = s.v_count = 2;
  const Eigen::Vector2d lo = box.min(), hi = box.max();
  s.u_knots = {lo.x(), lo.x(), hi.x(), hi.x()};
  s.v_knots = {lo.y(), lo.y(), hi.y(), hi.y()};
  for (double v : {lo.y(), hi.y()})
    for (double u : {lo.x(), hi.x()}) s.points.push_back(origin + u * e1 + v * e2);

  TrimLoop loop;
  for (size_t i = 0; i < n; ++i) loop.segments.push_back(Polyline2D{{uv[i], uv[(i + 1) % n]}});
  face.loops.push_back(std::move(loop));
  return face;
}

}  // namespace cadnurbs
