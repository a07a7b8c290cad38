#include "analysis/crease_normals.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "analysis/edge_sides.hpp"
#include "core/union_find.hpp"

namespace cadnurbs {

namespace {

double corner_angle(const Eigen::Vector3d& at, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d u = a - at, v = b - at;
  return std::atan2(u.cross(v).norm(), u.dot(v));  // accurate for small and obtuse angles alike
}

}  // namespace

TriangleMesh with_crease_normals(const TriangleMesh& welded, double crease_angle_radians, CreaseNormalsReport* report) {
  if (!(crease_angle_radians >= 0) || !std::isfinite(crease_angle_radians))
    throw std::invalid_argument("with_crease_normals: crease angle must be finite and >= 0, got " +
                                std::to_string(crease_angle_radians));
  validate(welded, "with_crease_normals input");
  const auto& P = welded.positions;
  const auto& T = welded.triangles;
  const size_t nt = T.size();

  std::vector<Eigen::Vector3d> face(nt);
  for (size_t t = 0; t < nt; ++t) {
    const Eigen::Vector3d n = (P[T[t][1]] - P[T[t][0]]).cross(P[T[t][2]] - P[T[t][0]]);
    const double length = n.norm();
    face[t] = length > 0 ? Eigen::Vector3d(n / length) : Eigen::Vector3d::Zero();
  }

  CreaseNormalsReport r;
  UnionFind groups(3 * nt);
  const EdgeSides edges = edge_sides(welded);
  for (std::size_t e = 0; e < edges.edge_count(); ++e) {
    const int count = edges.first[e + 1] - edges.first[e];
    if (count == 1) {
      ++r.boundary_edges;
    } else if (count > 2) {
      ++r.non_manifold_edges;
    } else {
      const int s1 = edges.sides[edges.first[e]], s2 = edges.sides[edges.first[e] + 1];
      const int t1 = s1 / 3, t2 = s2 / 3;
      if (side_from(welded, s1) == side_from(welded, s2)) {
        ++r.inconsistent_edges;
      } else if (face[t1].squaredNorm() == 0 || face[t2].squaredNorm() == 0) {
        ++r.sharp_edges;  // a zero-area face has no direction to be smooth with
      } else {
        // The angle between the normals by atan2 (acos loses digits near 0).
        const double angle = std::atan2(face[t1].cross(face[t2]).norm(), face[t1].dot(face[t2]));
        if (angle < crease_angle_radians) {
          ++r.smooth_edges;
          // The corner of t1 at each end of the edge joins t2's corner there; t2 runs the edge the other
          // way, so its side's end is t1's side's start.
          groups.unite(s1, 3 * t2 + (s2 % 3 + 1) % 3);
          groups.unite(3 * t1 + (s1 % 3 + 1) % 3, s2);
        } else {
          ++r.sharp_edges;
        }
      }
    }
  }

  std::vector<Eigen::Vector3d> sum(3 * nt, Eigen::Vector3d::Zero());
  for (size_t t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      const double weight = corner_angle(P[T[t][k]], P[T[t][(k + 1) % 3]], P[T[t][(k + 2) % 3]]);
      sum[groups.find(static_cast<int>(3 * t + k))] += weight * face[t];
    }

  TriangleMesh out;
  out.positions = P;
  out.triangles = T;
  out.corner_normals.resize(3 * nt);
  for (size_t c = 0; c < 3 * nt; ++c) {
    const int root = groups.find(static_cast<int>(c));
    if (root == static_cast<int>(c)) ++r.distinct_normals;
    const double length = sum[root].norm();
    out.corner_normals[c] = length > 0 ? Eigen::Vector3d(sum[root] / length) : face[c / 3];
  }
  if (report) *report = r;
  return out;
}

}  // namespace cadnurbs
