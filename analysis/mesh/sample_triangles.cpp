#include "analysis/mesh/sample_triangles.hpp"

#include <algorithm>
#include <cmath>

namespace cadnurbs {

std::vector<Eigen::Vector3d> sample_triangles(const TriangleMesh& mesh, double spacing,
                                              std::vector<double>* area_weights) {
  std::vector<Eigen::Vector3d> points = mesh.positions;
  if (area_weights) area_weights->assign(points.size(), 0.0);
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.positions[t[0]];
    const Eigen::Vector3d& b = mesh.positions[t[1]];
    const Eigen::Vector3d& c = mesh.positions[t[2]];
    const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    const int n = std::clamp(static_cast<int>(std::ceil(longest / spacing)), 3, 64);
    const double share = 0.5 * (b - a).cross(c - a).norm() / ((n + 1) * (n + 2) / 2);
    if (area_weights)
      for (int k = 0; k < 3; ++k) (*area_weights)[t[k]] += share;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const int k = n - i - j;
        if (i == n || j == n || k == n) continue;
        points.push_back((a * k + b * i + c * j) / n);
        if (area_weights) area_weights->push_back(share);
      }
  }
  return points;
}

double default_sample_spacing(const TriangleMesh& mesh) {
  double total = 0;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) total += (mesh.positions[t[k]] - mesh.positions[t[(k + 1) % 3]]).norm();
  return mesh.triangles.empty() ? 0.0 : total / (3.0 * 3.0 * mesh.triangles.size());
}

}  // namespace cadnurbs
