#include "core/interpolate_curve.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/geometry_error.hpp"
#include "core/knot_vector.hpp"

namespace cadnurbs {

namespace {

void check_data(const std::vector<Eigen::Vector3d>& points, const std::vector<double>& parameters, int degree,
                const std::string& entity) {
  const int count = static_cast<int>(points.size());
  if (count < 2) throw GeometryError(entity, std::to_string(count) + " points; at least 2 are needed");
  if (parameters.size() != points.size())
    throw GeometryError(entity, std::to_string(parameters.size()) + " parameters for " + std::to_string(count) +
                                    " points");
  if (degree < 1) throw GeometryError(entity, "degree " + std::to_string(degree) + " is below 1");
  for (int k = 0; k < count; ++k) {
    if (!points[k].allFinite() || !std::isfinite(parameters[k]))
      throw GeometryError(entity, "point or parameter " + std::to_string(k) + " is not finite");
    if (k > 0 && !(parameters[k] > parameters[k - 1]))
      throw GeometryError(entity, "parameters " + std::to_string(k - 1) + " and " + std::to_string(k) +
                                      " do not increase");
  }
}

}  // namespace

NurbsCurve interpolate_curve(const std::vector<Eigen::Vector3d>& points, const std::vector<double>& parameters,
                             int degree, int dimension) {
  const std::string entity = "curve interpolation";
  check_data(points, parameters, degree, entity);
  const int count = static_cast<int>(points.size());
  const int p = std::min(degree, count - 1);
  NurbsCurve curve;
  curve.dimension = dimension;
  curve.order = p + 1;
  // Averaging (P&T eq. 9.8): each interior knot the mean of p consecutive parameters, so every basis
  // function's support holds a parameter and the system is non-singular (Schoenberg-Whitney).
  curve.knots.assign(p + 1, parameters.front());
  for (int j = 1; j < count - p; ++j) {
    double sum = 0.0;
    for (int i = j; i < j + p; ++i) sum += parameters[i];
    curve.knots.push_back(sum / p);
  }
  curve.knots.insert(curve.knots.end(), p + 1, parameters.back());

  // Row k holds the p + 1 non-zero basis values at parameters[k], columns span - p .. span; stored as a
  // band, band(k, c - k + p), for columns k - p .. k + p (elimination fills in at most up to k + p).
  const int width = 2 * p + 1;
  Eigen::MatrixXd band = Eigen::MatrixXd::Zero(count, width);
  std::vector<double> basis(p + 1);
  for (int k = 0; k < count; ++k) {
    const int span = find_knot_span(curve.knots, curve.order, count, parameters[k]);
    basis_function_derivatives(curve.knots, curve.order, span, parameters[k], 0, basis.data(), p + 1);
    for (int a = 0; a <= p; ++a) {
      const int c = span - p + a;
      if (std::abs(c - k) <= p) band(k, c - k + p) = basis[a];
    }
  }
  std::vector<Eigen::Vector3d> rhs = points;
  for (int k = 0; k < count; ++k) {
    const double pivot = band(k, p);
    for (int i = k + 1; i <= std::min(count - 1, k + p); ++i) {
      const double below = band(i, k - i + p);
      if (below == 0.0) continue;
      const double f = below / pivot;
      for (int c = k; c <= std::min(count - 1, k + p); ++c) band(i, c - i + p) -= f * band(k, c - k + p);
      rhs[i] -= f * rhs[k];
    }
  }
  curve.points.resize(count);
  for (int k = count - 1; k >= 0; --k) {
    Eigen::Vector3d x = rhs[k];
    for (int c = k + 1; c <= std::min(count - 1, k + p); ++c) x -= band(k, c - k + p) * curve.points[c];
    curve.points[k] = x / band(k, p);
  }
  // The ends are the data's, bit for bit (the end rows are unit rows; said here, not left to rounding).
  curve.points.front() = points.front();
  curve.points.back() = points.back();
  if (!std::all_of(curve.points.begin(), curve.points.end(), [](const Eigen::Vector3d& q) { return q.allFinite(); }))
    throw GeometryError(entity, "the interpolation system is singular (parameters too close together)");
  return curve;
}

}  // namespace cadnurbs
