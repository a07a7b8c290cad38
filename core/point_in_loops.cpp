#include "core/point_in_loops.hpp"

#include <algorithm>
#include <cmath>

namespace cadnurbs {

PointInLoops::PointInLoops(std::vector<std::vector<Eigen::Vector2d>> loops) : loops_(std::move(loops)) {
  size_t edges = 0;
  double vmin = 1e300, vmax = -1e300;
  for (const auto& loop : loops_) {
    edges += loop.size();
    for (const auto& p : loop) vmin = std::min(vmin, p.y()), vmax = std::max(vmax, p.y());
  }
  if (edges == 0) return;
  const int n = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(edges))));
  v0_ = vmin;
  band_height_ = vmax > vmin ? (vmax - vmin) / n : 1.0;
  bands_.assign(n, {});
  for (const auto& loop : loops_)
    for (size_t i = 0; i < loop.size(); ++i) {
      const Eigen::Vector2d& a = loop[i];
      const Eigen::Vector2d& b = loop[(i + 1) % loop.size()];
      if (a.y() == b.y()) continue;  // horizontal edges never cross a horizontal ray (half-open rule)
      const int first = band_of(std::min(a.y(), b.y())), last = band_of(std::max(a.y(), b.y()));
      for (int k = first; k <= last; ++k) bands_[k].push_back({a, b});
    }
}

int PointInLoops::band_of(double v) const {
  const int k = static_cast<int>(std::floor((v - v0_) / band_height_));
  return std::clamp(k, 0, static_cast<int>(bands_.size()) - 1);
}

bool PointInLoops::inside(const Eigen::Vector2d& p) const {
  if (loops_.empty()) return true;
  if (bands_.empty()) return false;
  bool in = false;
  for (const Edge& e : bands_[band_of(p.y())]) {
    if ((e.a.y() > p.y()) == (e.b.y() > p.y())) continue;
    const double u = e.a.x() + (p.y() - e.a.y()) * (e.b.x() - e.a.x()) / (e.b.y() - e.a.y());
    if (u > p.x()) in = !in;
  }
  return in;
}

std::vector<double> PointInLoops::crossings(double v) const {
  std::vector<double> out;
  if (bands_.empty()) return out;
  for (const Edge& e : bands_[band_of(v)]) {
    if ((e.a.y() > v) == (e.b.y() > v)) continue;
    out.push_back(e.a.x() + (v - e.a.y()) * (e.b.x() - e.a.x()) / (e.b.y() - e.a.y()));
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace cadnurbs
