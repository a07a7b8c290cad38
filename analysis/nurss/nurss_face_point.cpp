#include "analysis/nurss/nurss_face_point.hpp"

namespace cadnurbs {

std::vector<double> nurss_corner_factors(const NurssMesh& mesh, NurssFaceId f) {
  const auto& p = mesh.corners(f);
  const int n = static_cast<int>(p.size());
  std::vector<double> before(n), after(n), c(n);  // d(P_{k-1} → P_k), d(P_{k+1} → P_k)
  double sum = 0;
  for (int k = 0; k < n; ++k) {
    before[k] = mesh.interval(p[(k + n - 1) % n], p[k]);
    after[k] = mesh.interval(p[(k + 1) % n], p[k]);
    c[k] = before[k] * after[k];
    sum += c[k];
  }
  if (sum > 0) return c;
  for (int k = 0; k < n; ++k) {
    c[k] = before[k] + after[k];
    sum += c[k];
  }
  if (sum > 0) return c;
  return std::vector<double>(n, 1.0);
}

Eigen::Vector4d nurss_face_point(const NurssMesh& mesh, NurssFaceId f) {
  return nurss_face_point(mesh, f, nurss_corner_factors(mesh, f));
}

Eigen::Vector4d nurss_face_point(const NurssMesh& mesh, NurssFaceId f, const std::vector<double>& c) {
  const auto& p = mesh.corners(f);
  Eigen::Vector4d v = Eigen::Vector4d::Zero();
  double sum = 0;
  for (size_t k = 0; k < p.size(); ++k) {
    v += c[k] * mesh.homogeneous(p[k]);
    sum += c[k];
  }
  return v / sum;
}

}  // namespace cadnurbs
