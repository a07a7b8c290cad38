#include "core/curve_distance_bound.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "core/bernstein_polynomial.hpp"
#include "core/bezier_extraction.hpp"
#include "core/knot_insertion.hpp"
#include "core/knot_vector.hpp"

namespace cadnurbs {

namespace {

// `c` with each of `breaks` it lacks inserted once: its spans then end at every one of them. (The other
// curve's domain ends are `c`'s own: the domains are equal.)
NurbsCurve split_at(const NurbsCurve& c, const std::vector<double>& breaks) {
  std::vector<double> missing;
  for (double t : breaks)
    if (!std::binary_search(c.knots.begin(), c.knots.end(), t)) missing.push_back(t);
  return missing.empty() ? c : refine_knots(c, missing);
}

BernsteinPolynomial<Eigen::Vector3d> bernstein_form(const NurbsCurve& piece) {
  BernsteinPolynomial<Eigen::Vector3d> p(piece.degree(), 0, Eigen::Vector3d::Zero());
  for (int i = 0; i <= piece.degree(); ++i) p.at(i, 0) = piece.points[i];
  return p;
}

}  // namespace

std::vector<SpanDistance> curve_distance_bounds(const NurbsCurve& a, const NurbsCurve& b) {
  if (a.is_rational() || b.is_rational()) throw std::invalid_argument("curve_distance_bound: a rational curve");
  if (a.dimension != b.dimension) throw std::invalid_argument("curve_distance_bound: curves of different dimensions");
  if (a.domain_start() != b.domain_start() || a.domain_end() != b.domain_end())
    throw std::invalid_argument("curve_distance_bound: curves on different domains");
  const std::vector<NurbsCurve> pieces_a = bezier_segments(split_at(a, domain_breaks(b.knots, b.order, b.count())));
  const std::vector<NurbsCurve> pieces_b = bezier_segments(split_at(b, domain_breaks(a.knots, a.order, a.count())));
  if (pieces_a.size() != pieces_b.size()) throw std::logic_error("curve_distance_bound: the spans do not match");
  std::vector<SpanDistance> spans;
  for (size_t i = 0; i < pieces_a.size(); ++i)
    spans.push_back({pieces_a[i].domain_start(), pieces_a[i].domain_end(),
                     largest_coefficient(bernstein_sum(bernstein_form(pieces_a[i]), bernstein_form(pieces_b[i]), -1.0))});
  return spans;
}

double curve_distance_bound(const NurbsCurve& a, const NurbsCurve& b) {
  double bound = 0;
  for (const SpanDistance& span : curve_distance_bounds(a, b)) bound = std::max(bound, span.bound);
  return bound;
}

}  // namespace cadnurbs
