#include "analysis/subd_nurbs/cubic_spline_fit.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>

#include "core/knot_vector.hpp"

namespace cadnurbs::subd_nurbs {

namespace {

// Row a: the basis functions of `knots` at params[a].
Eigen::MatrixXd collocation(const std::vector<double>& knots, const std::vector<double>& params) {
  const int count = static_cast<int>(knots.size()) - 4;
  Eigen::MatrixXd matrix = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(params.size()), count);
  double values[4], left[4], right[4];
  for (size_t a = 0; a < params.size(); ++a) {
    const int span = find_knot_span(knots, 4, count, params[a]);
    basis_function_values(knots.data(), 4, span, params[a], values, left, right);
    for (int j = 0; j < 4; ++j) matrix(static_cast<Eigen::Index>(a), span - 3 + j) = values[j];
  }
  return matrix;
}

}  // namespace

std::vector<double> graded_cubic_knots(int levels, bool halved) {
  std::vector<double> knots(4, 0.0);
  for (int j = levels; j >= 1; --j) knots.push_back(std::ldexp(1.0, -j));
  for (int j = 2; j <= levels; ++j) knots.push_back(1 - std::ldexp(1.0, -j));
  if (halved)
    for (int j = 2; j <= levels; ++j)
      knots.insert(knots.end(), {1.5 * std::ldexp(1.0, -j), 1 - 1.5 * std::ldexp(1.0, -j)});
  std::sort(knots.begin() + 4, knots.end());
  knots.insert(knots.end(), 4, 1.0);
  return knots;
}

std::vector<double> sample_params(const std::vector<double>& knots, int per_span, int end_steps) {
  std::vector<double> t;
  for (size_t k = 3; k + 4 < knots.size(); ++k)
    for (int q = 0; q <= per_span; ++q) t.push_back(knots[k] + (knots[k + 1] - knots[k]) * q / per_span);
  const double end_span = knots[4];
  for (int j = 1; j <= end_steps; ++j) t.insert(t.end(), {std::ldexp(end_span, -j), 1 - std::ldexp(end_span, -j)});
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end()), t.end());
  return t;
}

std::vector<Eigen::Vector3d> fit_cubic_curve(const std::vector<double>& knots, const std::vector<double>& params,
                                             const std::vector<Eigen::Vector3d>& samples, const Eigen::Vector3d& first,
                                             const Eigen::Vector3d& last) {
  const Eigen::MatrixXd basis = collocation(knots, params);
  const int count = static_cast<int>(knots.size()) - 4;
  Eigen::MatrixXd rest(basis.rows(), 3);
  for (Eigen::Index a = 0; a < basis.rows(); ++a)
    rest.row(a) = (samples[a] - basis(a, 0) * first - basis(a, count - 1) * last).transpose();
  const Eigen::MatrixXd inner = basis.middleCols(1, count - 2).colPivHouseholderQr().solve(rest);
  std::vector<Eigen::Vector3d> points(count);
  points.front() = first;
  points.back() = last;
  for (int i = 1; i < count - 1; ++i) points[i] = inner.row(i - 1).transpose();
  return points;
}

void fit_cubic_surface_interior(const std::vector<double>& knots, const std::vector<double>& params,
                                const std::vector<Eigen::Vector3d>& samples, std::vector<Eigen::Vector3d>& points) {
  const Eigen::MatrixXd basis = collocation(knots, params);
  const int count = static_cast<int>(knots.size()) - 4;
  const auto size = static_cast<Eigen::Index>(params.size());
  const auto solver = basis.middleCols(1, count - 2).colPivHouseholderQr();
  for (int c = 0; c < 3; ++c) {
    Eigen::MatrixXd held = Eigen::MatrixXd::Zero(count, count);  // (u index, v index), interior 0
    for (int j = 0; j < count; ++j)
      for (int i = 0; i < count; ++i)
        if (i == 0 || j == 0 || i == count - 1 || j == count - 1) held(i, j) = points[i + count * j][c];
    Eigen::MatrixXd rest(size, size);  // (u sample, v sample)
    for (Eigen::Index b = 0; b < size; ++b)
      for (Eigen::Index a = 0; a < size; ++a) rest(a, b) = samples[a + size * b][c];
    rest -= basis * held * basis.transpose();
    const Eigen::MatrixXd half = solver.solve(rest);                           // (inner u, v sample)
    const Eigen::MatrixXd inner = solver.solve(half.transpose()).transpose();  // (inner u, inner v)
    for (int j = 1; j < count - 1; ++j)
      for (int i = 1; i < count - 1; ++i) points[i + count * j][c] = inner(i - 1, j - 1);
  }
}

}  // namespace cadnurbs::subd_nurbs
