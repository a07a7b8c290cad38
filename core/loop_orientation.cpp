#include "core/loop_orientation.hpp"

#include <Eigen/Geometry>
#include <algorithm>

#include "core/point_in_loops.hpp"
#include "core/polygon_2d.hpp"

namespace cadnurbs {

namespace {

struct SampledLoop {
  std::vector<Eigen::Vector2d> polygon;
  Eigen::AlignedBox2d box;
  double signed_area = 0;
};

SampledLoop sample(const TrimLoop& loop) {
  SampledLoop s;
  s.polygon = loop_polygon(loop, 8);
  s.signed_area = polygon_signed_area(s.polygon);
  for (const auto& p : s.polygon) s.box.extend(p);
  return s;
}

// Points spread along the loop, at midpoints of polygon edges (vertices are where loops touch).
std::vector<Eigen::Vector2d> probes(const std::vector<Eigen::Vector2d>& polygon) {
  constexpr size_t count = 9;
  std::vector<Eigen::Vector2d> out;
  const size_t n = polygon.size();
  const size_t step = std::max<size_t>(1, n / count);
  for (size_t i = 0; i < n && out.size() < count; i += step)
    out.push_back(0.5 * (polygon[i] + polygon[(i + 1) % n]));
  return out;
}

}  // namespace

void orient_loops(std::vector<TrimLoop>& loops) {
  std::vector<SampledLoop> sampled;
  sampled.reserve(loops.size());
  for (const auto& loop : loops) sampled.push_back(sample(loop));
  std::vector<PointInLoops> regions;  // each loop alone: containment in one loop, not in the face
  regions.reserve(loops.size());
  for (const auto& s : sampled) regions.emplace_back(std::vector<std::vector<Eigen::Vector2d>>{s.polygon});
  for (size_t i = 0; i < loops.size(); ++i) {
    if (sampled[i].polygon.size() < 3) continue;
    const auto points = probes(sampled[i].polygon);
    int depth = 0;
    for (size_t j = 0; j < loops.size(); ++j) {
      if (j == i || sampled[j].polygon.size() < 3 || !sampled[j].box.intersects(sampled[i].box)) continue;
      size_t votes = 0;
      for (const auto& p : points) votes += regions[j].inside(p) ? 1 : 0;
      if (2 * votes > points.size()) ++depth;
    }
    const bool want_ccw = depth % 2 == 0;
    if ((sampled[i].signed_area > 0) != want_ccw) loops[i] = reversed(loops[i]);
  }
}

}  // namespace cadnurbs
