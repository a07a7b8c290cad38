#include "formats/vrml/transform_fields.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <stdexcept>

namespace cadnurbs {

TransformFields decompose_transform(const Eigen::Affine3d& transform) {
  if (!transform.matrix().allFinite()) throw std::invalid_argument("transform is not finite");
  const Eigen::Matrix3d m = transform.linear();
  // Singular value decomposition m = u diag(sigma) v^T through the eigenvectors of m^T m (well
  // conditioned enough for transforms, which are far from singular; Eigen's JacobiSVD trips a false
  // -Wmaybe-uninitialized in GCC 12).
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.compute(m.transpose() * m);
  const Eigen::Vector3d squares = eigen.eigenvalues().cwiseMax(0.0);
  Eigen::Vector3d sigma = squares.cwiseSqrt();
  if (!(sigma.minCoeff() > 1e-12 * sigma.maxCoeff()) || !(sigma.maxCoeff() > 0.0))
    throw std::invalid_argument("transform is singular");
  Eigen::Matrix3d v = eigen.eigenvectors();
  Eigen::Matrix3d u = m * v * sigma.cwiseInverse().asDiagonal();
  // Re-orthonormalise u (round-off of nearly equal singular values).
  const Eigen::HouseholderQR<Eigen::Matrix3d> qr(u);
  Eigen::Matrix3d q = qr.householderQ();
  for (int k = 0; k < 3; ++k)
    if (q.col(k).dot(u.col(k)) < 0) q.col(k) *= -1;
  u = q;
  // m = u diag(sigma) v^T. Make v a rotation (flipping a column of both keeps the product) ...
  if (v.determinant() < 0) {
    v.col(2) *= -1;
    u.col(2) *= -1;
  }
  // ... then u: a mirror is left as a negative scale factor.
  if (u.determinant() < 0) {
    u.col(2) *= -1;
    sigma(2) *= -1;
  }
  TransformFields fields;
  fields.translation = transform.translation();
  fields.rotation = Eigen::AngleAxisd(Eigen::Matrix3d(u * v.transpose()));
  fields.scale = sigma;
  // m = (u v^T) (v S v^T): v is the scale orientation. Any orientation fits a uniform scale.
  const bool uniform = (sigma.cwiseAbs().maxCoeff() - sigma.cwiseAbs().minCoeff()) <= 1e-12 * sigma.cwiseAbs().maxCoeff() &&
                       sigma.minCoeff() > 0;
  if (uniform) {
    fields.scale = Eigen::Vector3d::Constant(sigma.mean());
  } else {
    fields.scale_orientation = Eigen::AngleAxisd(Eigen::Matrix3d(v));
  }
  return fields;
}

Eigen::Affine3d compose_transform(const TransformFields& f) {
  Eigen::Affine3d m = Eigen::Affine3d::Identity();
  m.translate(f.translation + f.center);
  m.rotate(f.rotation);
  m.rotate(f.scale_orientation);
  m.scale(f.scale);
  m.rotate(f.scale_orientation.inverse());
  m.translate(-f.center);
  return m;
}

}  // namespace cadnurbs
