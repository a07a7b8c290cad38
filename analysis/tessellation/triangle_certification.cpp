#include "analysis/tessellation/triangle_certification.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/point_triangle_distance.hpp"

namespace cadnurbs::tessellation {

namespace {

using Barycentric = Eigen::Vector3d;

// Pieces of triangle abc between the C0 knot lines of `bound`, as barycentric corners (convex
// polygons, fanned). Records the longest cut in v.crosses_c0 / v.c0_point.
std::vector<std::array<Barycentric, 3>> pieces(const SurfaceDeviationBound& bound, const Eigen::Vector2d& a,
                                               const Eigen::Vector2d& b, const Eigen::Vector2d& c, TriangleVerdict& v) {
  std::vector<std::vector<Barycentric>> polys{{Barycentric(1, 0, 0), Barycentric(0, 1, 0), Barycentric(0, 0, 1)}};
  auto at = [&](const Barycentric& l) { return Eigen::Vector2d(l[0] * a + l[1] * b + l[2] * c); };
  double best_chord = -1;
  auto cut = [&](const std::vector<double>& lines, int axis) {
    const double lo = std::min({a[axis], b[axis], c[axis]}), hi = std::max({a[axis], b[axis], c[axis]});
    for (auto it = std::upper_bound(lines.begin(), lines.end(), lo); it != lines.end() && *it < hi; ++it) {
      const double x = *it;
      std::vector<std::vector<Barycentric>> next;
      std::vector<Barycentric> on_line;
      for (const auto& poly : polys) {
        std::vector<Barycentric> left, right;
        for (size_t k = 0; k < poly.size(); ++k) {
          const Barycentric& p = poly[k];
          const Barycentric& q = poly[(k + 1) % poly.size()];
          const double fp = at(p)[axis] - x, fq = at(q)[axis] - x;
          if (fp <= 0) left.push_back(p);
          if (fp >= 0) right.push_back(p);
          if ((fp < 0 && fq > 0) || (fp > 0 && fq < 0)) {
            const Barycentric m = p + (q - p) * (fp / (fp - fq));
            left.push_back(m), right.push_back(m), on_line.push_back(m);
          }
        }
        if (left.size() >= 3) next.push_back(left);
        if (right.size() >= 3) next.push_back(right);
      }
      polys = std::move(next);
      if (on_line.size() >= 2) {
        v.crosses_c0 = true;
        Eigen::Vector2d p0 = at(on_line.front()), p1 = p0;
        for (const auto& m : on_line) {
          const Eigen::Vector2d q = at(m);
          if ((q - p0).norm() > (p1 - p0).norm()) p1 = q;
        }
        if ((p1 - p0).norm() > best_chord) best_chord = (p1 - p0).norm(), v.c0_point = 0.5 * (p0 + p1);
      }
    }
  };
  cut(bound.c0_u, 0);
  cut(bound.c0_v, 1);
  std::vector<std::array<Barycentric, 3>> out;
  for (const auto& poly : polys)
    for (size_t k = 1; k + 1 < poly.size(); ++k) out.push_back({poly[0], poly[k], poly[k + 1]});
  return out;
}

// Whether a C0 knot line of `bound` passes strictly between the triangle's corners (when none does,
// pieces() gives the whole triangle: most triangles, and no allocation then).
bool meets_c0_line(const SurfaceDeviationBound& bound, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                   const Eigen::Vector2d& c) {
  auto meets = [&](const std::vector<double>& lines, int axis) {
    const double lo = std::min({a[axis], b[axis], c[axis]}), hi = std::max({a[axis], b[axis], c[axis]});
    const auto it = std::upper_bound(lines.begin(), lines.end(), lo);
    return it != lines.end() && *it < hi;
  };
  return meets(bound.c0_u, 0) || meets(bound.c0_v, 1);
}

// Narrows [lo, hi] to the C0 lines on either side of x, the piece's inside.
void between_lines(const std::vector<double>& lines, double x, double& lo, double& hi) {
  const auto above = std::upper_bound(lines.begin(), lines.end(), x);
  if (above != lines.end()) hi = std::min(hi, *above);
  if (above != lines.begin()) lo = std::max(lo, *(above - 1));
  lo = std::min(lo, hi);
}

}  // namespace

TriangleVerdict certify_triangle(SurfacePointCache& e, const SurfaceDeviationBound& bound, const MeshCorner& A,
                                 const MeshCorner& B, const MeshCorner& C, double d) {
  const MeshCorner* corners[3] = {&A, &B, &C};
  TriangleVerdict v;
  v.peak = (A.uv + B.uv + C.uv) / 3.0;
  for (int k = 0; k < 3; ++k) v.sampled = std::max(v.sampled, corners[k]->error.norm());
  // Distance to the triangle's plane (the chordal deviation): a point of the surface may lie over
  // a neighbouring triangle, which a distance to this triangle would count as error. A triangle
  // collapsed in 3D (at a pole) has no plane: distance to it (to its sides) then.
  const Eigen::Vector3d cross = (B.point - A.point).cross(C.point - A.point);
  const bool plane = cross.norm() > 1e-12 * (B.point - A.point).norm() * (C.point - A.point).norm() && cross.norm() > 0;
  const Eigen::Vector3d normal = plane ? Eigen::Vector3d(cross.normalized()) : Eigen::Vector3d::Zero();
  static const std::array<Barycentric, 3> whole_triangle{Barycentric(1, 0, 0), Barycentric(0, 1, 0), Barycentric(0, 0, 1)};
  const bool is_cut = meets_c0_line(bound, A.uv, B.uv, C.uv);
  const std::vector<std::array<Barycentric, 3>> cut = is_cut ? pieces(bound, A.uv, B.uv, C.uv, v) : std::vector<std::array<Barycentric, 3>>{};
  const std::array<Barycentric, 3>* parts_begin = is_cut ? cut.data() : &whole_triangle;
  const std::array<Barycentric, 3>* parts_end = is_cut ? cut.data() + cut.size() : &whole_triangle + 1;
  // Error at a point of the triangle: cached at its corners, evaluated elsewhere.
  auto error_at = [&](const Barycentric& l) {
    for (int q = 0; q < 3; ++q)
      if (l[q] == 1.0) return corners[q]->error.norm();
    const Eigen::Vector2d uv = l[0] * A.uv + l[1] * B.uv + l[2] * C.uv;
    return plane ? std::abs(normal.dot(e.point(uv.x(), uv.y()) - A.point))
                 : point_triangle_distance(e.point(uv.x(), uv.y()), A.point, B.point, C.point);
  };
  double total = 0;
  for (const std::array<Barycentric, 3>* it = parts_begin; it != parts_end; ++it) {
    const std::array<Barycentric, 3>& piece = *it;
    Eigen::Vector2d corner[3];
    for (int k = 0; k < 3; ++k) corner[k] = piece[k][0] * A.uv + piece[k][1] * B.uv + piece[k][2] * C.uv;
    double u0 = std::min({corner[0].x(), corner[1].x(), corner[2].x()});
    double u1 = std::max({corner[0].x(), corner[1].x(), corner[2].x()});
    double v0 = std::min({corner[0].y(), corner[1].y(), corner[2].y()});
    double v1 = std::max({corner[0].y(), corner[1].y(), corner[2].y()});
    if (is_cut) {
      // A piece lies between two neighbouring C0 lines; its corners on a line are interpolated and may
      // stray an ulp across it, which would bring in the patch beyond (hammer.iges: a patch 0.003 wide
      // with second derivatives 70 times its neighbour's, beyond a trimmed face's edge).
      const Eigen::Vector2d centre = (corner[0] + corner[1] + corner[2]) / 3.0;
      between_lines(bound.c0_u, centre.x(), u0, u1);
      between_lines(bound.c0_v, centre.y(), v0, v1);
    }
    const auto m = bound.over(u0, u1, v0, v1);
    const double whole = triangle_deviation_bound(corner[0], corner[1], corner[2], m);
    // The rigorous bound alone may do (flat or nearly flat pieces): no sampling then. A piece's corners
    // on a C0 line are points of the crease, which may lie far off the triangle's plane (a chord cutting
    // a profile's corner between two flat pieces): their errors count like the mesh corners'.
    double corner_error = 0;
    for (const Barycentric& l : piece) corner_error = std::max(corner_error, error_at(l));
    if (corner_error + whole <= d) {
      total = std::max(total, corner_error + whole);
      continue;
    }
    double piece_bound = 0;
    for (int k = 3; k <= 12; k *= 2) {
      double sampled = 0;
      for (int i = 0; i <= k; ++i)
        for (int j = 0; i + j <= k; ++j) {
          const Barycentric l = (piece[0] * (k - i - j) + piece[1] * i + piece[2] * j) / k;
          const bool mesh_corner = l[0] == 1.0 || l[1] == 1.0 || l[2] == 1.0;
          const double err = error_at(l);
          sampled = std::max(sampled, err);
          if (err >= v.sampled && !mesh_corner) {
            v.sampled = err;
            v.peak = l[0] * A.uv + l[1] * B.uv + l[2] * C.uv;
            v.peak_side = l[2] == 0 ? std::optional<int>(0) : l[0] == 0 ? std::optional<int>(1)
                        : l[1] == 0 ? std::optional<int>(2) : std::nullopt;
          }
        }
      piece_bound = sampled + whole / (k * k);
      if (sampled > d || piece_bound <= d) break;
    }
    total = std::max(total, piece_bound);
  }
  v.bound = total;
  v.ok = total <= d;
  return v;
}

}  // namespace cadnurbs::tessellation
