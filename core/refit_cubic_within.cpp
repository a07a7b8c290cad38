#include "core/refit_cubic_within.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/bezier_extraction.hpp"
#include "core/curve_distance_bound.hpp"
#include "core/knot_vector.hpp"

namespace cadnurbs {

namespace {

constexpr int kOrder = 4;
// Samples per span of the fit (its start among them): more than the unknowns a span adds, so that no span
// is fitted from too few, and enough that the curve's shape between samples shows.
constexpr int kSamplesPerSpan = 8;
// Chords per Bézier piece when its image's length is estimated.
constexpr int kLengthChords = 8;
// No piece is given less than this share of the parameter (a piece whose image is a point still needs an
// interval of its own).
constexpr double kLeastShare = 1e-6;

// The curve as a chain of Bézier pieces with its breakpoints at `at` (at.size() = pieces + 1, increasing):
// each piece keeps its control points, so the chain is the curve, reparametrised linearly piece by piece.
NurbsCurve chain(const std::vector<NurbsCurve>& pieces, const std::vector<double>& at) {
  NurbsCurve r;
  r.dimension = pieces.front().dimension;
  r.order = pieces.front().order;
  const int degree = r.order - 1;
  r.knots.assign(r.order, at.front());
  r.points = pieces.front().points;
  for (size_t i = 1; i < pieces.size(); ++i) {
    r.knots.insert(r.knots.end(), degree, at[i]);
    r.points.insert(r.points.end(), pieces[i].points.begin() + 1, pieces[i].points.end());
  }
  r.knots.insert(r.knots.end(), r.order, at.back());
  return r;
}

// Where each piece starts in [0, 1], in proportion to the lengths of the pieces' images; empty where the
// curve's image has no length.
std::vector<double> length_shares(const std::vector<NurbsCurve>& pieces) {
  std::vector<double> lengths;
  for (const auto& piece : pieces) {
    double length = 0;
    Eigen::Vector3d previous = piece.points.front();
    for (int k = 1; k <= kLengthChords; ++k) {
      const double t = piece.domain_start() + (piece.domain_end() - piece.domain_start()) * k / kLengthChords;
      const Eigen::Vector3d p = curve_point(piece, t);
      length += (p - previous).norm();
      previous = p;
    }
    lengths.push_back(length);
  }
  double total = 0;
  for (double l : lengths) total += l;
  if (!(total > 0) || !std::isfinite(total)) return {};
  std::vector<double> at{0.0};
  double sum = 0;
  for (double l : lengths) sum += std::max(l, kLeastShare * total), at.push_back(sum);
  for (double& a : at) a /= sum;
  at.back() = 1.0;
  return at;
}

// The least-squares cubic on `knots` (clamped, on r's domain) through r's end points.
std::optional<NurbsCurve> least_squares_cubic(const NurbsCurve& r, std::vector<double> knots) {
  NurbsCurve fit;
  fit.dimension = r.dimension;
  fit.order = kOrder;
  fit.knots = std::move(knots);
  const int count = static_cast<int>(fit.knots.size()) - kOrder;
  const Eigen::Vector3d first = r.points.front(), last = r.points.back();
  fit.points.assign(count, first);
  fit.points.back() = last;
  const int unknowns = count - 2;
  if (unknowns > 0) {
    std::vector<double> samples;  // kSamplesPerSpan in each span, its start among them, and the end
    for (int span = kOrder - 1; span < count; ++span)
      for (int k = 0; k < kSamplesPerSpan; ++k)
        samples.push_back(fit.knots[span] + (fit.knots[span + 1] - fit.knots[span]) * k / kSamplesPerSpan);
    samples.push_back(fit.knots.back());
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(unknowns, 3);
    double n[kOrder], left[kOrder], right[kOrder];
    for (double s : samples) {
      const int span = find_knot_span(fit.knots, kOrder, count, s);
      basis_function_values(fit.knots.data(), kOrder, span, s, n, left, right);
      Eigen::Vector3d residual = curve_point(r, s);
      for (int j = 0; j < kOrder; ++j) {
        const int i = span - kOrder + 1 + j;
        if (i == 0) residual -= n[j] * first;
        if (i == count - 1) residual -= n[j] * last;
      }
      for (int j = 0; j < kOrder; ++j) {
        const int i = span - kOrder + 1 + j;
        if (i == 0 || i == count - 1) continue;
        rhs.row(i - 1) += n[j] * residual.transpose();
        for (int l = 0; l < kOrder; ++l) {
          const int m = span - kOrder + 1 + l;
          if (m != 0 && m != count - 1) entries.emplace_back(i - 1, m - 1, n[j] * n[l]);
        }
      }
    }
    Eigen::SparseMatrix<double> normal(unknowns, unknowns);
    normal.setFromTriplets(entries.begin(), entries.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(normal);
    if (solver.info() != Eigen::Success) return std::nullopt;
    const Eigen::MatrixXd inner = solver.solve(rhs);
    if (solver.info() != Eigen::Success || !inner.allFinite()) return std::nullopt;
    for (int i = 0; i < unknowns; ++i) fit.points[i + 1] = inner.row(i).transpose();
  }
  if (fit.dimension == 2)
    for (auto& p : fit.points) p.z() = 0;
  return fit;
}

// The certified fit of the pieces placed at `shares` of [0, 1] with the fewest points this finds: from one
// span, every span whose bound exceeds the tolerance is halved and the whole fitted again, until every
// span passes (nullopt where that takes as many points as the curve has). Halving keeps every knot a
// multiple of 2^-depth; the result is scaled by 2^depth onto whole numbers (an affine change of parameter:
// the same curve, and the same bound against R scaled alike).
std::optional<NurbsCurve> fewest_points(const NurbsCurve& curve, const std::vector<NurbsCurve>& pieces,
                                        const std::vector<double>& shares, double tolerance) {
  const NurbsCurve r = chain(pieces, shares);
  std::vector<double> breaks{0.0, 1.0};  // the fit's distinct knots
  double finest = 1.0;
  while (static_cast<int>(breaks.size()) + kOrder - 2 < curve.count()) {
    std::vector<double> knots(kOrder - 1, 0.0);
    knots.insert(knots.end(), breaks.begin(), breaks.end());
    knots.insert(knots.end(), kOrder - 1, 1.0);
    std::optional<NurbsCurve> fit = least_squares_cubic(r, knots);
    if (!fit) return std::nullopt;
    std::vector<double> too_far(breaks.size() - 1, 0.0);  // per span of the fit, the largest bound inside
    size_t span = 0;
    for (const SpanDistance& d : curve_distance_bounds(*fit, r)) {
      while (span + 2 < breaks.size() && d.start >= breaks[span + 1]) ++span;
      too_far[span] = std::max(too_far[span], d.bound);
    }
    std::vector<double> split{0.0};
    for (size_t i = 0; i + 1 < breaks.size(); ++i) {
      if (too_far[i] > tolerance) split.push_back(0.5 * (breaks[i] + breaks[i + 1]));
      split.push_back(breaks[i + 1]);
    }
    if (split.size() == breaks.size()) {
      const double scale = 1.0 / finest;  // a power of two: the knots become whole numbers exactly
      for (double& k : fit->knots) k *= scale;
      return fit;
    }
    for (size_t i = 0; i + 1 < split.size(); ++i) finest = std::min(finest, split[i + 1] - split[i]);
    breaks = std::move(split);
  }
  return std::nullopt;
}

}  // namespace

std::optional<NurbsCurve> refit_cubic_within(const NurbsCurve& curve, double tolerance) {
  if (curve.is_rational() || curve.count() <= kOrder || !(tolerance > 0)) return std::nullopt;
  const std::vector<NurbsCurve> pieces = bezier_segments(curve);
  if (pieces.empty()) return std::nullopt;
  const std::vector<double> by_length = length_shares(pieces);
  if (by_length.empty()) return std::nullopt;
  // The curve's own parameter, mapped onto [0, 1] as a whole (no kinks where its speed was smooth).
  std::vector<double> own{0.0};
  const double a = curve.domain_start(), b = curve.domain_end();
  for (const auto& piece : pieces) own.push_back((piece.domain_end() - a) / (b - a));
  own.back() = 1.0;
  std::optional<NurbsCurve> best = fewest_points(curve, pieces, own, tolerance);
  std::optional<NurbsCurve> other = fewest_points(curve, pieces, by_length, tolerance);
  if (other && (!best || other->count() < best->count())) best = std::move(other);
  return best;
}

}  // namespace cadnurbs
