#include "core/split_curve.hpp"

#include <algorithm>
#include <string>

#include "core/geometry_error.hpp"
#include "core/knot_insertion.hpp"

namespace cadnurbs {

std::pair<NurbsCurve, NurbsCurve> split_curve(const NurbsCurve& curve, double t) {
  if (!(t > curve.domain_start() && t < curve.domain_end()))
    throw GeometryError("split curve", "parameter " + std::to_string(t) + " is not inside the curve's domain");
  const int p = curve.degree();
  const int existing = static_cast<int>(std::count(curve.knots.begin(), curve.knots.end(), t));
  const NurbsCurve full = existing < p ? insert_knot(curve, t, p - existing) : curve;
  const int multiplicity = std::max(existing, p);  // p: continuous at t; p + 1: the curve jumps there
  // The knots equal to t are full.knots[s .. s + multiplicity - 1]; the basis function N_{s-1} is 1 at t.
  const int s = static_cast<int>(std::lower_bound(full.knots.begin(), full.knots.end(), t) - full.knots.begin());
  const int first_after = s - 1 + (multiplicity - p);

  NurbsCurve before = full, after = full;
  before.points.assign(full.points.begin(), full.points.begin() + s);
  before.knots.assign(full.knots.begin(), full.knots.begin() + s + p);
  before.knots.push_back(t);
  after.points.assign(full.points.begin() + first_after, full.points.end());
  after.knots.assign(1, t);
  after.knots.insert(after.knots.end(), full.knots.begin() + first_after + 1, full.knots.end());
  if (full.is_rational()) {
    before.weights.assign(full.weights.begin(), full.weights.begin() + s);
    after.weights.assign(full.weights.begin() + first_after, full.weights.end());
  }
  return {std::move(before), std::move(after)};
}

}  // namespace cadnurbs
