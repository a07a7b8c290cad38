#include "core/rational_derivatives.hpp"

#include "core/binomial.hpp"

namespace cadnurbs {

std::vector<Eigen::Vector3d> rational_curve_derivatives(const std::vector<Eigen::Vector4d>& homogeneous) {
  const int d = static_cast<int>(homogeneous.size()) - 1;
  std::vector<Eigen::Vector3d> ck(d + 1);
  const double w0 = homogeneous[0][3];
  for (int k = 0; k <= d; ++k) {
    Eigen::Vector3d v = homogeneous[k].head<3>();
    for (int i = 1; i <= k; ++i) v -= binomial(k, i) * homogeneous[i][3] * ck[k - i];
    ck[k] = v / w0;
  }
  return ck;
}

std::vector<std::vector<Eigen::Vector3d>> rational_surface_derivatives(
    const std::vector<std::vector<Eigen::Vector4d>>& homogeneous) {
  const int d = static_cast<int>(homogeneous.size()) - 1;
  std::vector<std::vector<Eigen::Vector3d>> skl(d + 1, std::vector<Eigen::Vector3d>(d + 1, Eigen::Vector3d::Zero()));
  const double w00 = homogeneous[0][0][3];
  for (int k = 0; k <= d; ++k) {
    for (int l = 0; l <= d - k; ++l) {
      Eigen::Vector3d v = homogeneous[k][l].head<3>();
      for (int j = 1; j <= l; ++j) v -= binomial(l, j) * homogeneous[0][j][3] * skl[k][l - j];
      for (int i = 1; i <= k; ++i) {
        v -= binomial(k, i) * homogeneous[i][0][3] * skl[k - i][l];
        Eigen::Vector3d v2 = Eigen::Vector3d::Zero();
        for (int j = 1; j <= l; ++j) v2 += binomial(l, j) * homogeneous[i][j][3] * skl[k - i][l - j];
        v -= binomial(k, i) * v2;
      }
      skl[k][l] = v / w00;
    }
  }
  return skl;
}

}  // namespace cadnurbs
