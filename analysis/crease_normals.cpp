#include "analysis/crease_normals.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "analysis/edge_sides.hpp"
#include "core/triangle_normal.hpp"
#include "core/union_find.hpp"

namespace cadnurbs {

namespace {

double corner_angle(const Eigen::Vector3d& at, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d u = a - at, v = b - at;
  return std::atan2(u.cross(v).norm(), u.dot(v));  // accurate for small and obtuse angles alike
}

Eigen::Vector3d unit_face_normal(const TriangleMesh& mesh, size_t t) {
  const auto& T = mesh.triangles[t];
  return unit_normal(mesh.positions[T[0]], mesh.positions[T[1]], mesh.positions[T[2]]);
}

// Joins the corners that share a normal: for each smooth edge, the two corners at each of its ends.
UnionFind smooth_corner_groups(const TriangleMesh& mesh, double crease_angle_radians, CreaseNormalsReport& r) {
  UnionFind groups(3 * mesh.triangles.size());
  const EdgeSides edges = edge_sides(mesh);
  for (std::size_t e = 0; e < edges.edge_count(); ++e) {
    const int count = edges.first[e + 1] - edges.first[e];
    if (count == 1) {
      ++r.boundary_edges;
    } else if (count > 2) {
      ++r.non_manifold_edges;
    } else {
      const int s1 = edges.sides[edges.first[e]], s2 = edges.sides[edges.first[e] + 1];
      const int t1 = s1 / 3, t2 = s2 / 3;
      // Face normals are made here, twice per face, rather than kept: a table of them would be the
      // largest thing alive at this point.
      const Eigen::Vector3d n1 = unit_face_normal(mesh, t1), n2 = unit_face_normal(mesh, t2);
      if (side_from(mesh, s1) == side_from(mesh, s2)) {
        ++r.inconsistent_edges;
      } else if (n1.squaredNorm() == 0 || n2.squaredNorm() == 0) {
        ++r.sharp_edges;  // a zero-area face has no direction to be smooth with
      } else if (std::atan2(n1.cross(n2).norm(), n1.dot(n2)) < crease_angle_radians) {  // acos loses digits near 0
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
  return groups;
}

}  // namespace

CornerNormals crease_normals(const TriangleMesh& welded, double crease_angle_radians, CreaseNormalsReport* report) {
  if (!(crease_angle_radians >= 0) || !std::isfinite(crease_angle_radians))
    throw std::invalid_argument("with_crease_normals: crease angle must be finite and >= 0, got " +
                                std::to_string(crease_angle_radians));
  validate(welded, "with_crease_normals input");
  const auto& P = welded.positions;
  const auto& T = welded.triangles;
  const size_t nt = T.size();

  CreaseNormalsReport r;
  CornerNormals out;
  out.corner_normal = smooth_corner_groups(welded, crease_angle_radians, r).into_class_numbers();
  int groups = 0;
  for (const int g : out.corner_normal) groups = std::max(groups, g + 1);
  r.distinct_normals = groups;

  // Each group's weighted sum, in increasing order of corners (its first corner starts it: 0 + x).
  out.normals.assign(static_cast<size_t>(groups), Eigen::Vector3d::Zero());
  for (size_t t = 0; t < nt; ++t) {
    const Eigen::Vector3d face_t = unit_face_normal(welded, t);
    for (int k = 0; k < 3; ++k) {
      const double weight = corner_angle(P[T[t][k]], P[T[t][(k + 1) % 3]], P[T[t][(k + 2) % 3]]);
      out.normals[out.corner_normal[3 * t + k]] += weight * face_t;
    }
  }
  std::vector<bool> cancelled(static_cast<size_t>(groups), false);
  for (int g = 0; g < groups; ++g) {
    Eigen::Vector3d& normal = out.normals[g];
    const double length = normal.norm();
    cancelled[g] = !(length > 0);
    if (length > 0) normal /= length;
  }
  // A cancelled group's corners each take their own face's normal: the first corner in the group's slot,
  // the others in new slots.
  std::vector<bool> slot_used(static_cast<size_t>(groups), false);
  for (size_t c = 0; c < 3 * nt; ++c) {
    const int g = out.corner_normal[c];
    if (!cancelled[g]) continue;
    if (!slot_used[g]) {
      slot_used[g] = true;
      out.normals[g] = unit_face_normal(welded, c / 3);
    } else {
      out.corner_normal[c] = static_cast<int>(out.normals.size());
      out.normals.push_back(unit_face_normal(welded, c / 3));
    }
  }
  if (report) *report = r;
  return out;
}

TriangleMesh with_crease_normals(TriangleMesh welded, double crease_angle_radians, CreaseNormalsReport* report) {
  const CornerNormals shared = crease_normals(welded, crease_angle_radians, report);
  welded.corner_normals.resize(shared.corner_normal.size());
  for (size_t c = 0; c < shared.corner_normal.size(); ++c) welded.corner_normals[c] = shared.normals[shared.corner_normal[c]];
  return welded;
}

}  // namespace cadnurbs
