#pragma once
// Even-odd point-in-region test against sampled trimming loops (closed polygons in (u,v)), the rule
// X_ITE and the VRML/X3D specifications use, so loop orientation does not matter. The one such test of
// the project: tessellation, trimmed area, deviation measurement and loop orientation all use it, so
// they agree on every point. Edges are bucketed in horizontal bands so a test costs about sqrt(edges).
#include <Eigen/Core>
#include <vector>

namespace cadnurbs {

class PointInLoops {
 public:
  // `loops`: closed polygons (last point != first); may be empty (then every point is inside).
  explicit PointInLoops(std::vector<std::vector<Eigen::Vector2d>> loops);

  // True when p is inside an odd number of loops.
  bool inside(const Eigen::Vector2d& p) const;

  // Sorted u values where the horizontal line v crosses the loops (even-odd: inside between
  // crossings 0-1, 2-3, ...).
  std::vector<double> crossings(double v) const;

  const std::vector<std::vector<Eigen::Vector2d>>& loops() const { return loops_; }

 private:
  struct Edge {
    Eigen::Vector2d a, b;
  };
  std::vector<std::vector<Eigen::Vector2d>> loops_;
  std::vector<std::vector<Edge>> bands_;
  double v0_ = 0, band_height_ = 1;
  int band_of(double v) const;
};

}  // namespace cadnurbs
