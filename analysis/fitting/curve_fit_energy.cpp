#include "analysis/fitting/curve_fit_energy.hpp"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/fitting/bezier_span_basis.hpp"
#include "analysis/eval/span_quadrature.hpp"

namespace cadnurbs {
namespace {

constexpr int kMaxOrder = 16;

// Homogeneous points (w·P, w), as Eigen 4-vectors.
using Vector4 = Eigen::Vector4d;
Vector4 homogeneous_point(const Eigen::Vector3d& point, double weight) {
  return Vector4(weight * point.x(), weight * point.y(), weight * point.z(), weight);
}

struct SpanData {
  int span = 0;  // knot index s of [u_s, u_{s+1}]
  double start = 0;
  double length = 0;
  double coefficients[kMaxOrder * kMaxOrder];  // bezier_span_basis
};

// Values, first and second derivatives of the order rational basis functions of a span at local u:
// rational[d][i] for the basis function s - degree + i, derivatives with respect to t.
struct RationalBasis {
  double rational[3][kMaxOrder];
};

RationalBasis rational_basis(const SpanData& span, int order, const double* weights, const double* bernstein) {
  RationalBasis out{};
  double basis[3][kMaxOrder] = {};
  const double scale[3] = {1.0, 1.0 / span.length, 1.0 / (span.length * span.length)};
  for (int d = 0; d < 3; ++d) {
    for (int i = 0; i < order; ++i) {
      double sum = 0;
      for (int r = 0; r < order; ++r) sum += bernstein[d * order + r] * span.coefficients[r * order + i];
      basis[d][i] = sum * scale[d] * weights[i];
    }
  }
  double w[3] = {0, 0, 0};
  for (int d = 0; d < 3; ++d) {
    for (int i = 0; i < order; ++i) w[d] += basis[d][i];
  }
  for (int i = 0; i < order; ++i) {
    const double r0 = basis[0][i] / w[0];
    const double r1 = (basis[1][i] - r0 * w[1]) / w[0];
    const double r2 = (basis[2][i] - 2 * r1 * w[1] - r0 * w[2]) / w[0];
    out.rational[0][i] = r0;
    out.rational[1][i] = r1;
    out.rational[2][i] = r2;
  }
  return out;
}

}  // namespace

CurveFitEvaluation evaluate_curve_fit_energy(const std::vector<double>& parameters,
                                             const std::vector<Eigen::Vector3d>& points, int order,
                                             const std::vector<double>& knots, const std::vector<double>& weights,
                                             const CurveFitEnergyTerms& terms, bool with_gradient) {
  const int count = static_cast<int>(weights.size());
  const int degree = order - 1;
  const int sample_count = static_cast<int>(parameters.size());
  const int span_count = count - degree;
  CurveFitEvaluation out;

  std::vector<SpanData> spans(span_count);
  for (int k = 0; k < span_count; ++k) {
    SpanData& span = spans[k];
    span.span = degree + k;
    span.start = knots[span.span];
    span.length = knots[span.span + 1] - span.start;
    bezier_span_basis(&knots[span.span - degree + 1], order, span.coefficients);
  }
  // Each sample's span (the samples are sorted; the last span keeps the domain's end).
  std::vector<int> sample_span(sample_count);
  {
    int k = 0;
    for (int j = 0; j < sample_count; ++j) {
      while (k + 1 < span_count && parameters[j] >= knots[spans[k].span + 1]) ++k;
      sample_span[j] = k;
    }
  }

  // Normal equations of the quadratic in the control points: data rows and fairness quadrature.
  // The normal matrix is banded (half-bandwidth degree) and symmetric: band(i, l - i) holds entry (l, i), l >= i.
  Eigen::MatrixXd band = Eigen::MatrixXd::Zero(count, order);
  Eigen::MatrixXd right = Eigen::MatrixXd::Zero(count, 3);
  std::vector<double> sample_rows(static_cast<size_t>(sample_count) * order);
  const double inverse_m = 1.0 / sample_count;
  double bernstein[3 * kMaxOrder];
  for (int j = 0; j < sample_count; ++j) {
    const SpanData& span = spans[sample_span[j]];
    const int first = span.span - degree;
    bernstein_with_derivatives(degree, (parameters[j] - span.start) / span.length, bernstein);
    const RationalBasis basis = rational_basis(span, order, &weights[first], bernstein);
    for (int i = 0; i < order; ++i) {
      sample_rows[static_cast<size_t>(j) * order + i] = basis.rational[0][i];
      right.row(first + i) += inverse_m * basis.rational[0][i] * points[j].transpose();
      for (int l = i; l < order; ++l) band(first + i, l - i) += inverse_m * basis.rational[0][i] * basis.rational[0][l];
    }
  }
  auto rule_of = [&](const SpanData& span) -> const QuadratureRule& {
    return fairness_rule(span.length, terms.minimum_gap, order);
  };
  if (terms.fairness > 0) {
    for (const SpanData& span : spans) {
      const int first = span.span - degree;
      const QuadratureRule& rule = rule_of(span);
      for (size_t q = 0; q < rule.nodes.size(); ++q) {
        bernstein_with_derivatives(degree, rule.nodes[q], bernstein);
        const RationalBasis basis = rational_basis(span, order, &weights[first], bernstein);
        const double factor = terms.fairness * rule.weights[q] * span.length;
        for (int i = 0; i < order; ++i) {
          for (int l = i; l < order; ++l) band(first + i, l - i) += factor * basis.rational[2][i] * basis.rational[2][l];
        }
      }
    }
  }
  // A ridge far below any real entry keeps the system definite where a span holds no sample.
  band.col(0).array() += 1e-13 * band.col(0).maxCoeff();

  std::vector<Eigen::Triplet<double>> triplets;  // the lower triangle, which SimplicialLDLT reads
  triplets.reserve(static_cast<size_t>(count) * order);
  for (int i = 0; i < count; ++i) {
    for (int l = i; l <= std::min(count - 1, i + degree); ++l) triplets.emplace_back(l, i, band(i, l - i));
  }
  Eigen::SparseMatrix<double> sparse(count, count);
  sparse.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(sparse);
  if (solver.info() != Eigen::Success || (solver.vectorD().array() <= 0).any()) {
    out.energy = std::numeric_limits<double>::infinity();
    return out;
  }
  const Eigen::MatrixXd solution = solver.solve(right);
  out.control_points.resize(count);
  for (int i = 0; i < count; ++i) out.control_points[i] = solution.row(i).transpose();

  // The energy's terms.
  std::vector<Eigen::Vector3d> residual(sample_count);
  for (int j = 0; j < sample_count; ++j) {
    const int first = spans[sample_span[j]].span - degree;
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int i = 0; i < order; ++i) c += sample_rows[static_cast<size_t>(j) * order + i] * out.control_points[first + i];
    residual[j] = c - points[j];
    out.data_energy += inverse_m * residual[j].squaredNorm();
  }
  double spread = 0;
  for (const SpanData& span : spans) spread += std::pow(terms.minimum_gap / span.length, 2);
  const double spread_factor = terms.knot_spread * terms.scale / span_count;
  double pull = 0;
  for (double w : weights) pull += (w - 1) * (w - 1);
  const double pull_factor = terms.weight_pull * terms.scale / count;

  // Fairness value and, with the gradient, everything over the Bézier form of each span.
  if (with_gradient) {
    out.knot_gradient.assign(knots.size(), 0.0);
    out.weight_gradient.assign(count, 0.0);
  }
  std::vector<Vector4> bezier(order), bezier_gradient(order);
  int j = 0;
  for (int k = 0; k < span_count; ++k) {
    const SpanData& span = spans[k];
    const int first = span.span - degree;
    const double h = span.length;
    for (int r = 0; r < order; ++r) {
      bezier[r].setZero();
      for (int i = 0; i < order; ++i) {
        bezier[r] += span.coefficients[r * order + i] * homogeneous_point(out.control_points[first + i], weights[first + i]);
      }
      bezier_gradient[r].setZero();
    }
    double gradient_start = 0, gradient_end = 0;  // dE/du_s and dE/du_{s+1} through the local parameter
    auto bezier_at = [&](int d) {  // d-th derivative in u of the span's homogeneous Bézier curve
      Vector4 sum = Vector4::Zero();
      for (int r = 0; r < order; ++r) sum += bernstein[d * order + r] * bezier[r];
      return sum;
    };
    if (terms.fairness > 0) {
      double integral = 0;
      const QuadratureRule& rule = rule_of(span);
      for (size_t q = 0; q < rule.nodes.size(); ++q) {
        bernstein_with_derivatives(degree, rule.nodes[q], bernstein);
        const Vector4 h0 = bezier_at(0), h1 = bezier_at(1), h2 = bezier_at(2);
        const double w0 = h0.w(), w1 = h1.w(), w2 = h2.w();
        const Eigen::Vector3d c0 = h0.head<3>() / w0;
        const Eigen::Vector3d c1 = (h1.head<3>() - w1 * c0) / w0;
        const Eigen::Vector3d c2 = (h2.head<3>() - 2 * w1 * c1 - w2 * c0) / w0;
        integral += rule.weights[q] * c2.squaredNorm();
        if (!with_gradient) continue;
        // Reverse mode through c2 = (A'' - 2 w' c' - w'' c) / w, c' = (A' - w' c) / w, c = A / w.
        const Eigen::Vector3d v = 2 * terms.fairness * rule.weights[q] / (h * h * h) * c2;
        Eigen::Vector3d g_c1 = -2 * w1 / w0 * v;
        Eigen::Vector3d g_c0 = -w2 / w0 * v;
        double g_w2 = -v.dot(c0) / w0;
        double g_w1 = -2 * v.dot(c1) / w0;
        double g_w0 = -v.dot(c2) / w0;
        const Eigen::Vector3d g_a2 = v / w0;
        const Eigen::Vector3d g_a1 = g_c1 / w0;
        g_w1 += -g_c1.dot(c0) / w0;
        g_c0 += -w1 / w0 * g_c1;
        g_w0 += -g_c1.dot(c1) / w0;
        const Eigen::Vector3d g_a0 = g_c0 / w0;
        g_w0 += -g_c0.dot(c0) / w0;
        for (int r = 0; r < order; ++r) {
          bezier_gradient[r].head<3>() += bernstein[r] * g_a0 + bernstein[order + r] * g_a1 + bernstein[2 * order + r] * g_a2;
          bezier_gradient[r].w() += bernstein[r] * g_w0 + bernstein[order + r] * g_w1 + bernstein[2 * order + r] * g_w2;
        }
      }
      out.fairness_energy += terms.fairness * integral / (h * h * h);
      // d/dh of fairness · integral / h³, with h = u_{s+1} - u_s.
      const double by_length = -3 * terms.fairness * integral / (h * h * h * h);
      gradient_start -= by_length;
      gradient_end += by_length;
    }
    if (!with_gradient) {
      while (j < sample_count && sample_span[j] == k) ++j;
      continue;
    }
    for (; j < sample_count && sample_span[j] == k; ++j) {
      const double u = (parameters[j] - span.start) / h;
      bernstein_with_derivatives(degree, u, bernstein);
      const Vector4 h0 = bezier_at(0), h1 = bezier_at(1);
      const Eigen::Vector3d c0 = h0.head<3>() / h0.w();
      const Eigen::Vector3d v = 2 * inverse_m * residual[j];
      const Eigen::Vector3d g_a = v / h0.w();
      const double g_w = -v.dot(c0) / h0.w();
      for (int r = 0; r < order; ++r) {
        bezier_gradient[r].head<3>() += bernstein[r] * g_a;
        bezier_gradient[r].w() += bernstein[r] * g_w;
      }
      // u = (t - u_s) / h: du/du_s = (t - u_{s+1}) / h², du/du_{s+1} = -(t - u_s) / h².
      const Eigen::Vector3d dc_du = (h1.head<3>() - h1.w() * c0) / h0.w();
      const double g_u = v.dot(dc_du);
      gradient_start += g_u * (parameters[j] - (span.start + h)) / (h * h);
      gradient_end += -g_u * (parameters[j] - span.start) / (h * h);
    }
    // Chain rule from the Bézier points to the weights (Pw_i = (w_i P_i, w_i), P_i held) and knots.
    for (int i = 0; i < order; ++i) {
      const Vector4 dpw = homogeneous_point(out.control_points[first + i], 1.0);  // d(w P, w)/dw
      double sum = 0;
      for (int r = 0; r < order; ++r) sum += span.coefficients[r * order + i] * bezier_gradient[r].dot(dpw);
      out.weight_gradient[first + i] += sum;
    }
    Dual local[2 * kMaxOrder];
    Dual derivative[kMaxOrder * kMaxOrder];
    for (int l = 0; l < 2 * degree; ++l) local[l] = Dual{knots[span.span - degree + 1 + l], 0};
    for (int l = 0; l < 2 * degree; ++l) {
      local[l].derivative = 1;
      bezier_span_basis(local, order, derivative);
      local[l].derivative = 0;
      double sum = 0;
      for (int r = 0; r < order; ++r) {
        Vector4 d_point = Vector4::Zero();
        for (int i = 0; i < order; ++i) {
          d_point += derivative[r * order + i].derivative *
                     homogeneous_point(out.control_points[first + i], weights[first + i]);
        }
        sum += bezier_gradient[r].dot(d_point);
      }
      out.knot_gradient[span.span - degree + 1 + l] += sum;
    }
    out.knot_gradient[span.span] += gradient_start;
    out.knot_gradient[span.span + 1] += gradient_end;
    // The knot-spread term: d/dh (gap / h)² = -2 gap² / h³.
    const double by_length = -2 * spread_factor * terms.minimum_gap * terms.minimum_gap / (h * h * h);
    out.knot_gradient[span.span] -= by_length;
    out.knot_gradient[span.span + 1] += by_length;
  }
  if (with_gradient) {
    for (int i = 0; i < count; ++i) out.weight_gradient[i] += 2 * pull_factor * (weights[i] - 1);
  }
  out.energy = out.data_energy + out.fairness_energy + spread_factor * spread + pull_factor * pull;
  return out;
}

}  // namespace cadnurbs
