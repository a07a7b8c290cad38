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

TriangleMesh with_crease_normals(TriangleMesh welded, double crease_angle_radians, CreaseNormalsReport* report) {
  if (!(crease_angle_radians >= 0) || !std::isfinite(crease_angle_radians))
    throw std::invalid_argument("with_crease_normals: crease angle must be finite and >= 0, got " +
                                std::to_string(crease_angle_radians));
  validate(welded, "with_crease_normals input");
  TriangleMesh out = std::move(welded);  // the same positions and triangles, new corner normals
  const auto& P = out.positions;
  const auto& T = out.triangles;
  const size_t nt = T.size();

  auto face_normal = [&](size_t t) -> Eigen::Vector3d {
    const Eigen::Vector3d n = (P[T[t][1]] - P[T[t][0]]).cross(P[T[t][2]] - P[T[t][0]]);
    const double length = n.norm();
    return length > 0 ? Eigen::Vector3d(n / length) : Eigen::Vector3d::Zero();
  };
  std::vector<Eigen::Vector3d> face(nt);  // for the edges; dropped before the corner normals are made
  for (size_t t = 0; t < nt; ++t) face[t] = face_normal(t);

  CreaseNormalsReport r;
  UnionFind groups(3 * nt);
  {
    const EdgeSides edges = edge_sides(out);
    for (std::size_t e = 0; e < edges.edge_count(); ++e) {
      const int count = edges.first[e + 1] - edges.first[e];
      if (count == 1) {
        ++r.boundary_edges;
      } else if (count > 2) {
        ++r.non_manifold_edges;
      } else {
        const int s1 = edges.sides[edges.first[e]], s2 = edges.sides[edges.first[e] + 1];
        const int t1 = s1 / 3, t2 = s2 / 3;
        if (side_from(out, s1) == side_from(out, s2)) {
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
  }

  face = {};

  // Each group's weighted sum is gathered in its root's slot, then normalised. A root is its group's
  // smallest corner, so in increasing order of corners it is reached first (its slot starts the sum, no
  // fill beforehand) and is finished before the group's other corners copy it.
  out.corner_normals.resize(3 * nt);
  for (size_t t = 0; t < nt; ++t) {
    const Eigen::Vector3d face_t = face_normal(t);
    for (int k = 0; k < 3; ++k) {
      const double weight = corner_angle(P[T[t][k]], P[T[t][(k + 1) % 3]], P[T[t][(k + 2) % 3]]);
      const int c = static_cast<int>(3 * t + k), root = groups.find(c);
      if (root == c)
        out.corner_normals[c] = Eigen::Vector3d::Zero() + weight * face_t;  // 0 + x: the sum's first term
      else
        out.corner_normals[root] += weight * face_t;
    }
  }
  std::vector<bool> cancelled(3 * nt, false);  // roots whose sum is zero: each corner takes its own face's
  for (size_t c = 0; c < 3 * nt; ++c) {
    const int root = groups.find(static_cast<int>(c));
    Eigen::Vector3d& normal = out.corner_normals[c];
    if (root == static_cast<int>(c)) {
      ++r.distinct_normals;
      const double length = normal.norm();
      cancelled[c] = !(length > 0);
      normal = length > 0 ? Eigen::Vector3d(normal / length) : face_normal(c / 3);
    } else {
      normal = cancelled[root] ? face_normal(c / 3) : out.corner_normals[root];
    }
  }
  if (report) *report = r;
  return out;
}

}  // namespace cadnurbs
