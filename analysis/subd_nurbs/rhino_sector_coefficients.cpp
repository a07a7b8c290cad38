#include "analysis/subd_nurbs/rhino_sector_coefficients.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/union_find.hpp"

namespace cadnurbs::subd_nurbs {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kAngleSteps = 72;  // corner angles are multiples of 2 pi / 72 (5 degrees)

// The angle at `corner` between the directions to a and b, as Rhino measures a corner sector: sine and
// cosine within 0.002 of 0 are 0, within 0.001 of 1 make the angle a right or a straight one.
double corner_angle(const Eigen::Vector3d& corner, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d da = (a - corner).normalized(), db = (b - corner).normalized();
  double c = da.dot(db), s = da.cross(db).norm();
  if (std::abs(c) <= 0.002) c = 0;
  if (std::abs(s) <= 0.002) s = 0;
  if (c == 0 || s >= 0.999) return kPi / 2;
  if (s == 0 || std::abs(c) >= 0.999) return c < 0 ? kPi : 0;
  const double angle = std::atan2(s, c);
  return std::abs(angle - kPi) <= 0.002 ? kPi : angle;
}

// The angle rounded to the nearest multiple of 2 pi / 72, between 1 and 36 of them (5 to 180 degrees).
double rounded_corner_angle(double angle) {
  const double step = 2 * kPi / kAngleSteps;
  const int steps = std::clamp(static_cast<int>(std::lround(angle / step)), 1, kAngleSteps / 2);
  return steps * step;
}

}  // namespace

double rhino_sector_coefficient(double theta) {
  double c = std::cos(theta);
  constexpr double kSnap = 1e-6;
  if (std::abs(c) <= kSnap)
    c = 0;
  else if (std::abs(std::abs(c) - 0.5) <= kSnap)
    c = std::copysign(0.5, c);
  else if (std::abs(c) + kSnap >= 1)
    c = std::copysign(1.0, c);
  return 0.5 + c / 3;
}

SectorCoefficients rhino_sector_coefficients(const SubdControlNet& net, const NetEdges& edges,
                                             const std::vector<PointTag>& tags) {
  // Per tagged point, its faces and each face's two neighbours of the point.
  struct Corner {
    int face, before, after;
  };
  std::vector<std::vector<Corner>> corners(net.points.size());
  for (size_t f = 0; f < net.faces.size(); ++f) {
    const auto& face = net.faces[f];
    const size_t n = face.size();
    for (size_t k = 0; k < n; ++k)
      if (tags[face[k]] != PointTag::smooth)
        corners[face[k]].push_back({static_cast<int>(f), face[(k + n - 1) % n], face[(k + 1) % n]});
  }
  auto edge_of = [&](int a, int b) -> const NetEdge& { return edges.at({std::min(a, b), std::max(a, b)}); };

  SectorCoefficients coefficients;
  for (size_t v = 0; v < corners.size(); ++v) {
    const auto& around = corners[v];
    if (around.empty()) continue;
    // Sectors: the faces around v joined across smooth edges (face i's "after" edge is some face's "before").
    UnionFind sectors(around.size());
    std::map<int, int> face_before;  // other point of a smooth edge -> index of the face that has it before
    for (size_t i = 0; i < around.size(); ++i)
      if (!edge_of(static_cast<int>(v), around[i].before).crease) face_before[around[i].before] = static_cast<int>(i);
    for (size_t i = 0; i < around.size(); ++i)
      if (const auto other = face_before.find(around[i].after); other != face_before.end())
        sectors.unite(static_cast<int>(i), other->second);
    std::map<int, int> sector_faces;
    std::map<int, std::vector<int>> sector_creases;  // other points of the crease edges bounding it
    for (size_t i = 0; i < around.size(); ++i) {
      const int s = sectors.find(static_cast<int>(i));
      ++sector_faces[s];
      for (int other : {around[i].before, around[i].after})
        if (edge_of(static_cast<int>(v), other).crease) sector_creases[s].push_back(other);
    }
    for (const auto& [other, i] : face_before) {
      const int s = sectors.find(i);
      const double faces = sector_faces[s];
      double theta = 0;
      switch (tags[v]) {
        case PointTag::crease:
          theta = kPi / faces;
          break;
        case PointTag::dart:
          theta = 2 * kPi / faces;
          break;
        default: {
          auto bounds = sector_creases[s];
          std::sort(bounds.begin(), bounds.end());
          bounds.erase(std::unique(bounds.begin(), bounds.end()), bounds.end());
          const double angle =
              bounds.size() == 2 ? corner_angle(net.points[v], net.points[bounds[0]], net.points[bounds[1]]) : kPi;
          theta = rounded_corner_angle(angle) / faces;
        }
      }
      if (const double w = rhino_sector_coefficient(theta); w != 0.5) coefficients[{static_cast<int>(v), other}] = w;
    }
  }
  return coefficients;
}

}  // namespace cadnurbs::subd_nurbs
