#include "formats/cnb/cnb_gate_shape.hpp"

namespace cadnurbs::cnb {

namespace {

struct Vec {
  double x, y, z;
};
Vec difference(const GridPoint& a, const GridPoint& b) {
  return {static_cast<double>(a[0] - b[0]), static_cast<double>(a[1] - b[1]), static_cast<double>(a[2] - b[2])};
}
double dot(const Vec& a, const Vec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec cross(const Vec& a, const Vec& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

}  // namespace

int gate_shape(const GridPoint& from, const GridPoint& to, const GridPoint& apex, const std::optional<GridPoint>& after) {
  if (!after) return 0;
  const Vec along = difference(to, from);
  const Vec normal = cross(along, difference(apex, from));
  const Vec u = difference(from, to), v = difference(*after, to);
  const double uu = dot(u, u), vv = dot(v, v), nn = dot(normal, normal);
  if (uu == 0 || vv == 0 || nn == 0) return 0;
  // The apex lies where (along x (p - from)) . normal > 0; w must lie where it is < 0.
  if (!(dot(cross(along, difference(*after, from)), normal) < 0)) return 0;
  const Vec candidate = cross(v, u);
  const double cn = dot(candidate, normal), cc = dot(candidate, candidate);
  if (!(cn * cn > 0.9801 * cc * nn)) return 1;
  const double uv = dot(u, v);
  // The angle at `to`: at least 120 degrees where cos <= -1/2, at least 60 where cos <= 1/2.
  if (uv <= 0 && uv * uv >= 0.25 * uu * vv) return 2;
  if (uv <= 0 || uv * uv <= 0.25 * uu * vv) return 3;
  return 4;
}

}  // namespace cadnurbs::cnb
