#include "formats/cnb/cnb_mesh_period.hpp"

#include <algorithm>
#include <map>
#include <unordered_set>

namespace cadnurbs::cnb {

namespace {
constexpr size_t sampled_points = 256;  // points whose grid lines propose moves
constexpr size_t moves_tried = 8;       // the most proposed, each counted over every point
constexpr int64_t fewest_mapped = 8;
}  // namespace

size_t GridPointHash::operator()(const GridPoint& p) const {
  uint64_t h = 1469598103934665603ull;
  for (int64_t x : p) h = (h ^ static_cast<uint64_t>(x)) * 1099511628211ull;
  return static_cast<size_t>(h ^ (h >> 29));
}

size_t PeriodPredictor::EdgeHash::operator()(const std::pair<int, int>& e) const {
  const uint64_t both = static_cast<uint64_t>(static_cast<uint32_t>(e.first)) << 32 | static_cast<uint32_t>(e.second);
  return static_cast<size_t>(both * 0x9E3779B97F4A7C15ull);
}

GridPoint dominant_period(const std::vector<GridPoint>& points) {
  if (points.size() < 2) return {0, 0, 0};
  std::unordered_set<GridPoint, GridPointHash> all(points.begin(), points.end());
  // Each axis's grid lines: the distinct points as (the other two coordinates, the value on the axis),
  // sorted, so that a line is a run.
  std::array<std::vector<GridPoint>, 3> lines;
  for (int k = 0; k < 3; ++k) {
    for (const auto& p : all) lines[k].push_back({p[(k + 1) % 3], p[(k + 2) % 3], p[k]});
    std::sort(lines[k].begin(), lines[k].end());
  }
  std::map<GridPoint, int64_t> proposed;
  const size_t stride = std::max<size_t>(1, points.size() / sampled_points);
  for (size_t i = 0; i < points.size(); i += stride) {
    const GridPoint& p = points[i];
    for (int k = 0; k < 3; ++k) {
      // The points after p on its line along axis k.
      auto at = std::upper_bound(lines[k].begin(), lines[k].end(), GridPoint{p[(k + 1) % 3], p[(k + 2) % 3], p[k]});
      for (; at != lines[k].end() && (*at)[0] == p[(k + 1) % 3] && (*at)[1] == p[(k + 2) % 3]; ++at) {
        GridPoint move{0, 0, 0};
        move[k] = (*at)[2] - p[k];
        ++proposed[move];
      }
    }
  }
  std::vector<std::pair<int64_t, GridPoint>> ranked;
  for (const auto& [move, count] : proposed) ranked.push_back({count, move});
  std::sort(ranked.begin(), ranked.end(),
            [](const auto& a, const auto& b) { return a.first > b.first || (a.first == b.first && a.second < b.second); });
  GridPoint best{0, 0, 0};
  int64_t best_mapped = std::max<int64_t>(fewest_mapped, static_cast<int64_t>(all.size() / 10)) - 1;
  for (size_t r = 0; r < ranked.size() && r < moves_tried; ++r) {
    const GridPoint& move = ranked[r].second;
    int64_t mapped = 0;
    for (const auto& p : all) mapped += all.count({p[0] + move[0], p[1] + move[1], p[2] + move[2]});
    if (mapped > best_mapped) best_mapped = mapped, best = move;
  }
  return best;
}

GridPoint PeriodCache::period_of(const std::vector<GridPoint>& points) {
  uint64_t key = points.size();
  for (const auto& p : points) key = key * 1099511628211ull ^ GridPointHash{}(p);
  auto& same_key = found_[key];
  for (const auto& [met, period] : same_key)
    if (met == points) return period;
  const GridPoint period = dominant_period(points);
  same_key.push_back({points, period});
  return period;
}

PeriodPredictor::PeriodPredictor(const GridPoint& period)
    : period_(period), active_(period[0] != 0 || period[1] != 0 || period[2] != 0) {}

void PeriodPredictor::add_vertex(int number, const GridPoint& p) {
  if (!active_) return;
  if (static_cast<size_t>(number) >= points_.size()) points_.resize(static_cast<size_t>(number) + 1);
  points_[static_cast<size_t>(number)] = p;
  first_at_.emplace(p, number);
}

void PeriodPredictor::add_triangle(int a, int b, int c) {
  if (!active_) return;
  apex_.emplace(std::pair{a, b}, c);
  apex_.emplace(std::pair{b, c}, a);
  apex_.emplace(std::pair{c, a}, b);
}

std::optional<GridPoint> PeriodPredictor::predict(const GridPoint& a, const GridPoint& b, const GridPoint& c) const {
  if (!active_) return std::nullopt;
  const auto at = [&](const GridPoint& p, const GridPoint& shift) {
    const auto found = first_at_.find({p[0] + shift[0], p[1] + shift[1], p[2] + shift[2]});
    return found == first_at_.end() ? -1 : found->second;
  };
  const auto apex_of = [&](int from, int to) {
    const auto found = apex_.find({from, to});
    return found == apex_.end() ? -1 : found->second;
  };
  // First where the gate's own triangle repeats too, then where only the far triangle does.
  for (const bool whole : {true, false})
    for (const int64_t sign : {-1, 1}) {
      const GridPoint shift{sign * period_[0], sign * period_[1], sign * period_[2]};
      const int a_there = at(a, shift), b_there = at(b, shift);
      if (a_there < 0 || b_there < 0) continue;
      if (whole && (apex_of(a_there, b_there) < 0 || apex_of(a_there, b_there) != at(c, shift))) continue;
      const int v = apex_of(b_there, a_there);
      if (v < 0) continue;
      const GridPoint& p = points_[static_cast<size_t>(v)];
      return GridPoint{p[0] - shift[0], p[1] - shift[1], p[2] - shift[2]};
    }
  return std::nullopt;
}

}  // namespace cadnurbs::cnb
