#include "analysis/normals/crease_normals.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "analysis/mesh/side_partners.hpp"
#include "core/triangle_normal.hpp"
#include "core/union_find.hpp"
#include "core/worker_threads.hpp"

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

// (b - a) x (c - a) for triangle t's corners a, b, c: unit_normal's vector before it is divided.
Eigen::Vector3d face_cross(const TriangleMesh& mesh, size_t t) {
  const auto& T = mesh.triangles[t];
  const Eigen::Vector3d& a = mesh.positions[T[0]];
  return (mesh.positions[T[1]] - a).cross(mesh.positions[T[2]] - a);
}

// unit_normal's result from face_cross's vector (the same operations, so the same bits).
Eigen::Vector3d unit(const Eigen::Vector3d& cross) {
  const double length = cross.norm();
  return length > 0 ? Eigen::Vector3d(cross / length) : Eigen::Vector3d::Zero();
}

// Whether two faces are joined: the angle atan2(|n1 x n2|, n1 . n2) between their unit normals is below
// the crease angle. Most edges are decided without the normalisations and the atan2, from the raw cross
// products c1, c2: tan^2 of their angle, |c1 x c2|^2 / (c1 . c2)^2, against tan^2 of the crease angle with a
// relative margin of 1e-7. Both ways of computing the angle's tangent are within about 1e-14 of the true
// one (an ulp or so of the normalisation, and cancellation in the cross products that is absolute, not
// relative, at the normals' unit scale), and the margin is over 1e-10 of the tangent for crease angles in
// [0.001, pi/2 - 0.001], so an edge decided that way is decided as the atan2 would. The rest (angles within
// the margin, faces at right angles or more, tiny or huge coordinates, other crease angles) take the atan2.
class SmoothTest {
 public:
  explicit SmoothTest(double crease_angle_radians)
      : angle_(crease_angle_radians),
        fast_(angle_ >= 1e-3 && angle_ <= std::numbers::pi / 2 - 1e-3),
        tan2_(std::tan(angle_) * std::tan(angle_)) {}

  // c1, c2: face_cross of the two faces. Zero-area faces are never joined (no direction to be smooth with).
  bool operator()(const Eigen::Vector3d& c1, const Eigen::Vector3d& c2) const {
    const double l1 = c1.squaredNorm(), l2 = c2.squaredNorm();
    const double x = c1.dot(c2);
    if (fast_ && l1 > 1e-100 && l1 < 1e100 && l2 > 1e-100 && l2 < 1e100 && x > 0) {
      const double y2 = c1.cross(c2).squaredNorm(), bound = x * x * tan2_;
      if (y2 < bound * (1 - 1e-7)) return true;
      if (y2 > bound * (1 + 1e-7)) return false;
    }
    const Eigen::Vector3d n1 = unit(c1), n2 = unit(c2);
    if (n1.squaredNorm() == 0 || n2.squaredNorm() == 0) return false;
    return std::atan2(n1.cross(n2).norm(), n1.dot(n2)) < angle_;  // acos loses digits near 0
  }

 private:
  double angle_;
  bool fast_;
  double tan2_;
};

// Joins the corners that share a normal: for each smooth edge, the two corners at each of its ends. The
// edges are judged in parallel (most of the work), the unions made after in one thread; which corners end
// up together does not depend on the order of the unions.
UnionFind smooth_corner_groups(const TriangleMesh& mesh, const SidePartners& sides, double crease_angle_radians,
                               CreaseNormalsReport& r) {
  const std::vector<int>& partner = sides.partner;
  r.boundary_edges = sides.boundary_edges;
  r.non_manifold_edges = sides.non_manifold_edges;
  const SmoothTest smooth_angle(crease_angle_radians);
  std::vector<char> smooth(partner.size(), 0);  // at the lower side of each smooth edge
  const int workers = worker_threads();
  std::vector<CreaseNormalsReport> counts(workers);
  on_workers(workers, [&](int w) {
    CreaseNormalsReport c;
    const auto [begin, end] = worker_range(partner.size(), w, workers);
    for (size_t s = begin; s < end; ++s) {
      const int p = partner[s];
      if (p < static_cast<int>(s)) continue;  // each two-face edge once
      if (side_from(mesh, static_cast<int>(s)) == side_from(mesh, p)) {
        ++c.inconsistent_edges;
      } else if (smooth_angle(face_cross(mesh, s / 3), face_cross(mesh, p / 3))) {
        ++c.smooth_edges;
        smooth[s] = 1;
      } else {
        ++c.sharp_edges;
      }
    }
    counts[w] = c;
  });
  for (const CreaseNormalsReport& c : counts) {
    r.inconsistent_edges += c.inconsistent_edges;
    r.sharp_edges += c.sharp_edges;
    r.smooth_edges += c.smooth_edges;
  }
  UnionFind groups(partner.size());
  for (size_t s = 0; s < partner.size(); ++s) {
    if (!smooth[s]) continue;
    const int s1 = static_cast<int>(s), s2 = partner[s];
    // The corner of t1 at each end of the edge joins t2's corner there; t2 runs the edge the other way,
    // so its side's end is t1's side's start.
    groups.unite(s1, 3 * (s2 / 3) + (s2 % 3 + 1) % 3);
    groups.unite(3 * (s1 / 3) + (s1 % 3 + 1) % 3, s2);
  }
  return groups;
}

}  // namespace

CornerNormals crease_normals(const TriangleMesh& welded, double crease_angle_radians, CreaseNormalsReport* report,
                             const SidePartners* partners) {
  if (!(crease_angle_radians >= 0) || !std::isfinite(crease_angle_radians))
    throw std::invalid_argument("with_crease_normals: crease angle must be finite and >= 0, got " +
                                std::to_string(crease_angle_radians));
  validate(welded, "with_crease_normals input");
  const auto& P = welded.positions;
  const auto& T = welded.triangles;
  const size_t nt = T.size();

  CreaseNormalsReport r;
  CornerNormals out;
  SidePartners made;
  if (!partners) {
    made = side_partners(welded);
    partners = &made;
  }
  if (partners->partner.size() != 3 * nt)
    throw std::invalid_argument("crease_normals: side partners of " + std::to_string(partners->partner.size()) +
                                " sides given for " + std::to_string(nt) + " triangles");
  out.corner_normal = smooth_corner_groups(welded, *partners, crease_angle_radians, r).into_class_numbers();
  const int workers = worker_threads();
  std::vector<int> groups_seen(workers, 0);  // each worker's highest group number + 1 in its corners
  on_workers(workers, [&](int w) {
    const auto [begin, end] = worker_range(out.corner_normal.size(), w, workers);
    for (size_t c = begin; c < end; ++c) groups_seen[w] = std::max(groups_seen[w], out.corner_normal[c] + 1);
  });
  const int groups = *std::max_element(groups_seen.begin(), groups_seen.end());
  r.distinct_normals = groups;

  // Each group's weighted sum, in increasing order of corners (its first corner starts it: 0 + x), then
  // divided by its length; a sum of length 0 marks the group cancelled. The groups are shared out in
  // ranges, each worker going through all triangles for the corners of its own, so that every sum is made
  // in the same order as by one thread.
  out.normals.assign(static_cast<size_t>(groups), Eigen::Vector3d::Zero());
  std::vector<char> cancelled(static_cast<size_t>(groups), 0);
  std::vector<char> cancelled_seen(workers, 0);
  on_workers(workers, [&](int w) {
    const WorkerRange range = worker_range(static_cast<size_t>(groups), w, workers);  // no binding: clang 14
    const size_t first_group = range.begin, end_group = range.end;                     // cannot capture one
    auto mine = [&](size_t c) {
      const auto g = static_cast<size_t>(out.corner_normal[c]);
      return g >= first_group && g < end_group;
    };
    for (size_t t = 0; t < nt; ++t) {
      if (!mine(3 * t) && !mine(3 * t + 1) && !mine(3 * t + 2)) continue;
      const Eigen::Vector3d face_t = unit_face_normal(welded, t);
      for (int k = 0; k < 3; ++k) {
        if (!mine(3 * t + k)) continue;
        const double weight = corner_angle(P[T[t][k]], P[T[t][(k + 1) % 3]], P[T[t][(k + 2) % 3]]);
        out.normals[out.corner_normal[3 * t + k]] += weight * face_t;
      }
    }
    for (size_t g = first_group; g < end_group; ++g) {
      Eigen::Vector3d& normal = out.normals[g];
      const double length = normal.norm();
      cancelled[g] = !(length > 0);
      cancelled_seen[w] |= cancelled[g];
      if (length > 0) normal /= length;
    }
  });
  // A cancelled group's corners each take their own face's normal: the first corner in the group's slot,
  // the others in new slots.
  if (std::find(cancelled_seen.begin(), cancelled_seen.end(), 1) != cancelled_seen.end()) {
    std::vector<char> slot_used(static_cast<size_t>(groups), 0);
    for (size_t c = 0; c < 3 * nt; ++c) {
      const int g = out.corner_normal[c];
      if (!cancelled[g]) continue;
      if (!slot_used[g]) {
        slot_used[g] = 1;
        out.normals[g] = unit_face_normal(welded, c / 3);
      } else {
        out.corner_normal[c] = static_cast<int>(out.normals.size());
        out.normals.push_back(unit_face_normal(welded, c / 3));
      }
    }
  }
  if (report) *report = r;
  return out;
}

TriangleMesh with_crease_normals(TriangleMesh welded, double crease_angle_radians, CreaseNormalsReport* report,
                                 const SidePartners* partners) {
  const CornerNormals shared = crease_normals(welded, crease_angle_radians, report, partners);
  welded.corner_normals.resize(shared.corner_normal.size());
  for (size_t c = 0; c < shared.corner_normal.size(); ++c) welded.corner_normals[c] = shared.normals[shared.corner_normal[c]];
  return welded;
}

}  // namespace cadnurbs
