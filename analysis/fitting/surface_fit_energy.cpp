#include "analysis/fitting/surface_fit_energy.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <cmath>
#include <limits>

#include "analysis/fitting/curve_fit_energy.hpp"
#include "analysis/eval/span_quadrature.hpp"
#include "core/knot_vector.hpp"

namespace cadnurbs {
namespace {

// One direction's curve system: K = collocationᵀ collocation / samples + fairness · bending, the matrix
// curve_fit_energy builds for the same knots (same quadrature, same tiny ridge), here dense.
struct DirectionSystem {
  Eigen::MatrixXd collocation;  // samples x count: N_a(t_s)
  Eigen::MatrixXd gram;         // collocationᵀ collocation / samples
  Eigen::MatrixXd bending;      // ∫ N_a'' N_b''
  Eigen::LLT<Eigen::MatrixXd> factor;
  bool definite = false;
};

DirectionSystem direction_system(const std::vector<double>& parameters, int order, const std::vector<double>& knots,
                                 const SurfaceFitEnergyTerms& terms) {
  const int count = static_cast<int>(knots.size()) - order;
  const int samples = static_cast<int>(parameters.size());
  DirectionSystem system;
  system.collocation = Eigen::MatrixXd::Zero(samples, count);
  double values[3 * kMaxStackOrder];
  for (int s = 0; s < samples; ++s) {
    const int span = find_knot_span(knots, order, count, parameters[s]);
    basis_function_derivatives(knots, order, span, parameters[s], 0, values, order);
    for (int r = 0; r < order; ++r) system.collocation(s, span - order + 1 + r) = values[r];
  }
  system.gram = system.collocation.transpose() * system.collocation / samples;
  system.bending = Eigen::MatrixXd::Zero(count, count);
  if (order >= 3) {
    for (int span = order - 1; span < count; ++span) {
      const double start = knots[span], length = knots[span + 1] - start;
      const QuadratureRule& rule = fairness_rule(length, terms.minimum_gap, order);
      for (size_t q = 0; q < rule.nodes.size(); ++q) {
        basis_function_derivatives(knots, order, span, start + rule.nodes[q] * length, 2, values, order);
        const double* second = values + 2 * order;
        for (int a = 0; a < order; ++a) {
          for (int b = 0; b < order; ++b) {
            system.bending(span - order + 1 + a, span - order + 1 + b) += rule.weights[q] * length * second[a] * second[b];
          }
        }
      }
    }
  }
  Eigen::MatrixXd k = system.gram + terms.fairness * system.bending;
  k.diagonal().array() += 1e-13 * k.diagonal().maxCoeff();
  system.factor.compute(k);
  system.definite = system.factor.info() == Eigen::Success;
  return system;
}

// The grid's coordinate c as an m x n matrix.
Eigen::MatrixXd coordinate(const GridSamples& grid, int c) {
  const int m = static_cast<int>(grid.u.size()), n = static_cast<int>(grid.v.size());
  Eigen::MatrixXd out(m, n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < m; ++i) out(i, j) = grid.points[i + j * m][c];
  }
  return out;
}

// The virtual data of the other direction's whitening, Z_c = data_c · other_collocation · L⁻ᵀ / samples
// (one column per control point of the other direction), as 3D points column by column.
std::vector<std::vector<Eigen::Vector3d>> virtual_data(const Eigen::MatrixXd (&data)[3], const DirectionSystem& other) {
  const Eigen::MatrixXd whitened =
      other.factor.matrixL().solve(other.collocation.transpose()).transpose() / other.collocation.rows();
  const Eigen::Index rows = data[0].rows(), columns = whitened.cols();
  std::vector<std::vector<Eigen::Vector3d>> out(columns, std::vector<Eigen::Vector3d>(rows));
  for (int c = 0; c < 3; ++c) {
    const Eigen::MatrixXd z = data[c] * whitened;
    for (Eigen::Index k = 0; k < columns; ++k) {
      for (Eigen::Index i = 0; i < rows; ++i) out[k][i][c] = z(i, k);
    }
  }
  return out;
}

double spread_energy(const std::vector<double>& knots, int order, const SurfaceFitEnergyTerms& terms) {
  const int count = static_cast<int>(knots.size()) - order;
  double sum = 0;
  for (int span = order - 1; span < count; ++span) sum += std::pow(terms.minimum_gap / (knots[span + 1] - knots[span]), 2);
  return terms.knot_spread * terms.scale * sum / (count - order + 1);
}

// Σ_k of the curve energies on the virtual data along one direction: their control points (one
// column each) and, when asked, their knot gradients summed into `gradient`. The spread term rides on
// the first column only, so it is counted once. False when a curve system is singular.
bool curve_energies(const std::vector<double>& parameters, const std::vector<std::vector<Eigen::Vector3d>>& columns,
                    int order, const std::vector<double>& knots, const SurfaceFitEnergyTerms& terms, bool with_gradient,
                    std::vector<std::vector<Eigen::Vector3d>>* control_points, std::vector<double>* gradient) {
  const int count = static_cast<int>(knots.size()) - order;
  const std::vector<double> weights(count, 1.0);
  CurveFitEnergyTerms curve_terms;
  curve_terms.fairness = terms.fairness;
  curve_terms.minimum_gap = terms.minimum_gap;
  curve_terms.scale = terms.scale;
  if (gradient) gradient->assign(knots.size(), 0.0);
  for (size_t k = 0; k < columns.size(); ++k) {
    curve_terms.knot_spread = k == 0 ? terms.knot_spread : 0.0;
    const CurveFitEvaluation e =
        evaluate_curve_fit_energy(parameters, columns[k], order, knots, weights, curve_terms, with_gradient);
    if (!std::isfinite(e.energy)) return false;
    if (control_points) control_points->push_back(e.control_points);
    if (gradient) {
      for (size_t i = 0; i < knots.size(); ++i) (*gradient)[i] += e.knot_gradient[i];
    }
  }
  return true;
}

}  // namespace

SurfaceFitEvaluation evaluate_surface_fit_energy(const GridSamples& grid, int u_order, int v_order,
                                                 const std::vector<double>& u_knots, const std::vector<double>& v_knots,
                                                 const SurfaceFitEnergyTerms& terms, bool with_gradient) {
  SurfaceFitEvaluation out;
  const int m = static_cast<int>(grid.u.size()), n = static_cast<int>(grid.v.size());
  const int u_count = static_cast<int>(u_knots.size()) - u_order, v_count = static_cast<int>(v_knots.size()) - v_order;
  const DirectionSystem u_system = direction_system(grid.u, u_order, u_knots, terms);
  const DirectionSystem v_system = direction_system(grid.v, v_order, v_knots, terms);
  if (!u_system.definite || !v_system.definite) {
    out.energy = std::numeric_limits<double>::infinity();
    return out;
  }
  Eigen::MatrixXd data[3], data_transposed[3];
  for (int c = 0; c < 3; ++c) {
    data[c] = coordinate(grid, c);
    data_transposed[c] = data[c].transpose();
  }

  // u knots: v whitened away, one curve fit in u per v control point. Its solutions Y = Q L_v give Q.
  std::vector<std::vector<Eigen::Vector3d>> u_curves;
  if (!curve_energies(grid.u, virtual_data(data, v_system), u_order, u_knots, terms, with_gradient, &u_curves,
                      with_gradient ? &out.u_knot_gradient : nullptr)) {
    out.energy = std::numeric_limits<double>::infinity();
    return out;
  }
  Eigen::MatrixXd q[3];  // u_count x v_count per coordinate
  for (int c = 0; c < 3; ++c) {
    Eigen::MatrixXd y(u_count, v_count);
    for (int k = 0; k < v_count; ++k) {
      for (int a = 0; a < u_count; ++a) y(a, k) = u_curves[k][a][c];
    }
    q[c] = v_system.factor.matrixU().solve(y.transpose()).transpose();  // Y L_v⁻¹
  }
  if (with_gradient) {
    // v knots: u whitened away, one curve fit in v per u control point (only the gradient is needed).
    if (!curve_energies(grid.v, virtual_data(data_transposed, u_system), v_order, v_knots, terms, true, nullptr,
                        &out.v_knot_gradient)) {
      out.energy = std::numeric_limits<double>::infinity();
      return out;
    }
  }

  // The energy from the residuals themselves (no cancellation against the data's size).
  out.control_points.resize(static_cast<size_t>(u_count) * v_count);
  for (int c = 0; c < 3; ++c) {
    const Eigen::MatrixXd residual = u_system.collocation * q[c] * v_system.collocation.transpose() - data[c];
    out.data_energy += residual.squaredNorm() / (static_cast<double>(m) * n);
    const Eigen::MatrixXd ru_q = u_system.bending * q[c], gu_q = u_system.gram * q[c];
    const Eigen::MatrixXd q_gv = q[c] * v_system.gram, q_rv = q[c] * v_system.bending;
    out.fairness_energy += terms.fairness * (ru_q.cwiseProduct(q_gv).sum() + gu_q.cwiseProduct(q_rv).sum()) +
                           terms.fairness * terms.fairness * ru_q.cwiseProduct(q_rv).sum();
    for (int b = 0; b < v_count; ++b) {
      for (int a = 0; a < u_count; ++a) out.control_points[a + b * u_count][c] = q[c](a, b);
    }
  }
  out.energy = out.data_energy + out.fairness_energy + spread_energy(u_knots, u_order, terms) +
               spread_energy(v_knots, v_order, terms);
  return out;
}

}  // namespace cadnurbs
