#include "core/knot_insertion.hpp"

#include <algorithm>
#include <iterator>
#include <string>

#include "core/geometry_error.hpp"
#include "core/knot_vector.hpp"

namespace cadnurbs {

namespace {

using HomogeneousRow = std::vector<Eigen::Vector4d>;

// Boehm's algorithm on one row of homogeneous points; knots are updated in place.
HomogeneousRow insert_into_row(const std::vector<double>& knots, int order, const HomogeneousRow& row, double t,
                               int times, int span, int multiplicity) {
  const int p = order - 1;
  const int n = static_cast<int>(row.size()) - 1;
  HomogeneousRow out(row.size() + times);
  for (int i = 0; i <= span - p; ++i) out[i] = row[i];
  for (int i = span - multiplicity; i <= n; ++i) out[i + times] = row[i];
  HomogeneousRow temp(p + 1);
  for (int i = 0; i <= p - multiplicity; ++i) temp[i] = row[span - p + i];
  int l = 0;
  for (int j = 1; j <= times; ++j) {
    l = span - p + j;
    for (int i = 0; i <= p - j - multiplicity; ++i) {
      const double alpha = (t - knots[l + i]) / (knots[i + span + 1] - knots[l + i]);
      temp[i] = alpha * temp[i + 1] + (1.0 - alpha) * temp[i];
    }
    out[l] = temp[0];
    out[span + times - j - multiplicity] = temp[p - j - multiplicity];
  }
  for (int i = l + 1; i < span - multiplicity; ++i) out[i] = temp[i - l];
  return out;
}

struct InsertionPlace {
  int span;
  int multiplicity;
};

InsertionPlace check_insertion(const std::vector<double>& knots, int order, int count, double t, int times) {
  if (times < 1) throw GeometryError("knot insertion", "times must be at least 1");
  if (t < knots[order - 1] || t > knots[count])
    throw GeometryError("knot insertion", "knot " + std::to_string(t) + " lies outside the domain");
  const int multiplicity = static_cast<int>(std::count(knots.begin(), knots.end(), t));
  if (multiplicity + times > order - 1)
    throw GeometryError("knot insertion", "knot " + std::to_string(t) + " would get multiplicity " +
                                              std::to_string(multiplicity + times) + " above the degree");
  // Span with knots[span] <= t < knots[span+1], also for t at the domain end.
  int span = static_cast<int>(std::upper_bound(knots.begin(), knots.end(), t) - knots.begin()) - 1;
  span = std::min(span, static_cast<int>(knots.size()) - 1);
  return {span, multiplicity};
}

std::vector<double> inserted_knots(const std::vector<double>& knots, double t, int times, int span) {
  std::vector<double> out(knots.begin(), knots.begin() + span + 1);
  out.insert(out.end(), times, t);
  out.insert(out.end(), knots.begin() + span + 1, knots.end());
  return out;
}

HomogeneousRow to_homogeneous(const std::vector<Eigen::Vector3d>& points, const std::vector<double>& weights) {
  HomogeneousRow row(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    const double w = weights.empty() ? 1.0 : weights[i];
    row[i] << w * points[i], w;
  }
  return row;
}

void from_homogeneous(const HomogeneousRow& row, bool rational, std::vector<Eigen::Vector3d>& points,
                      std::vector<double>& weights) {
  points.resize(row.size());
  weights.clear();
  if (rational) weights.resize(row.size());
  for (size_t i = 0; i < row.size(); ++i) {
    points[i] = row[i].head<3>() / row[i][3];
    if (rational) weights[i] = row[i][3];
  }
}

// The surface with every row along `direction` (in homogeneous form) replaced by rewrite(row), which
// returns `new_count` points; the knots in that direction become `new_knots`.
template <class Rewrite>
NurbsSurface rewrite_rows(const NurbsSurface& s, SurfaceDirection direction, int new_count, std::vector<double> new_knots,
                          Rewrite rewrite) {
  const bool in_u = direction == SurfaceDirection::u;
  const int count = in_u ? s.u_count : s.v_count;
  const int other = in_u ? s.v_count : s.u_count;
  NurbsSurface out = s;
  (in_u ? out.u_count : out.v_count) = new_count;
  (in_u ? out.u_knots : out.v_knots) = std::move(new_knots);
  out.points.assign(static_cast<size_t>(out.u_count) * out.v_count, Eigen::Vector3d::Zero());
  if (s.is_rational()) out.weights.assign(out.points.size(), 1.0);
  for (int r = 0; r < other; ++r) {
    HomogeneousRow row(count);
    for (int c = 0; c < count; ++c) {
      const int i = in_u ? c : r, j = in_u ? r : c;
      row[c] << s.weight(i, j) * s.point(i, j), s.weight(i, j);
    }
    const HomogeneousRow refined = rewrite(row);
    for (int c = 0; c < new_count; ++c) {
      const int i = in_u ? c : r, j = in_u ? r : c;
      out.points[out.index(i, j)] = refined[c].head<3>() / refined[c][3];
      if (s.is_rational()) out.weights[out.index(i, j)] = refined[c][3];
    }
  }
  return out;
}

}  // namespace

NurbsCurve insert_knot(const NurbsCurve& curve, double t, int times) {
  const auto place = check_insertion(curve.knots, curve.order, curve.count(), t, times);
  const auto row = insert_into_row(curve.knots, curve.order, to_homogeneous(curve.points, curve.weights), t, times,
                                   place.span, place.multiplicity);
  NurbsCurve out = curve;
  out.knots = inserted_knots(curve.knots, t, times, place.span);
  from_homogeneous(row, curve.is_rational(), out.points, out.weights);
  if (curve.dimension == 2)
    for (auto& p : out.points) p.z() = 0.0;
  return out;
}

NurbsSurface insert_knot(const NurbsSurface& s, SurfaceDirection direction, double t, int times) {
  const bool in_u = direction == SurfaceDirection::u;
  const auto& knots = in_u ? s.u_knots : s.v_knots;
  const int order = in_u ? s.u_order : s.v_order;
  const int count = in_u ? s.u_count : s.v_count;
  const auto place = check_insertion(knots, order, count, t, times);
  return rewrite_rows(s, direction, count + times, inserted_knots(knots, t, times, place.span), [&](const HomogeneousRow& row) {
    return insert_into_row(knots, order, row, t, times, place.span, place.multiplicity);
  });
}

namespace {

// Refuses what inserting the values one by one would refuse: a value outside the domain, a knot
// above the degree's multiplicity, values out of order.
void check_refinement(const std::vector<double>& knots, int order, int count, const std::vector<double>& new_knots) {
  for (size_t k = 0; k < new_knots.size(); ++k) {
    const double t = new_knots[k];
    if (k > 0 && t < new_knots[k - 1]) throw GeometryError("knot insertion", "new knots must be non-decreasing");
    if (t < knots[order - 1] || t > knots[count])
      throw GeometryError("knot insertion", "knot " + std::to_string(t) + " lies outside the domain");
    const size_t already = static_cast<size_t>(std::count(knots.begin(), knots.end(), t));
    const size_t added = static_cast<size_t>(std::upper_bound(new_knots.begin(), new_knots.end(), t) -
                                             std::lower_bound(new_knots.begin(), new_knots.end(), t));
    if (already + added > static_cast<size_t>(order - 1))
      throw GeometryError("knot insertion", "knot " + std::to_string(t) + " would get multiplicity " +
                                                std::to_string(already + added) + " above the degree");
  }
}

// Every value of x (sorted) inserted into one row at once (Boehm's refinement, Piegl & Tiller A5.4):
// the points outside the affected spans are copied, the others are computed once each from the
// right, so the cost is linear in the row, not in (row x new knots) as one insertion at a time.
// `ubar` is the refined knot vector (u and x merged); `row` becomes the refined row.
void refine_row(const std::vector<double>& u, const std::vector<double>& ubar, int order, const std::vector<double>& x,
                HomogeneousRow& row) {
  const int p = order - 1;
  const int n = static_cast<int>(row.size()) - 1, r = static_cast<int>(x.size()) - 1;
  auto span_of = [&](double t) {  // knots[span] <= t < knots[span + 1], the last span at the domain end
    if (t >= u[n + 1]) return n;
    return static_cast<int>(std::upper_bound(u.begin() + p, u.begin() + n + 1, t) - u.begin()) - 1;
  };
  const int a = span_of(x.front()), b = span_of(x.back()) + 1;
  HomogeneousRow q(row.size() + x.size());
  for (int j = 0; j <= a - p; ++j) q[j] = row[j];
  for (int j = b - 1; j <= n; ++j) q[j + r + 1] = row[j];
  int i = b + p - 1, k = b + p + r;
  for (int j = r; j >= 0; --j) {
    while (x[j] <= u[i] && i > a) {
      q[k - p - 1] = row[i - p - 1];
      --k, --i;
    }
    q[k - p - 1] = q[k - p];
    for (int l = 1; l <= p; ++l) {
      const int at = k - p + l;
      const double span = ubar[k + l] - x[j];
      if (span == 0.0) {
        q[at - 1] = q[at];
      } else {
        const double alpha = span / (ubar[k + l] - u[i - p + l]);
        q[at - 1] = alpha * q[at - 1] + (1.0 - alpha) * q[at];
      }
    }
    --k;
  }
  row = std::move(q);
}

std::vector<double> merged_knots(const std::vector<double>& knots, const std::vector<double>& new_knots) {
  std::vector<double> out;
  out.reserve(knots.size() + new_knots.size());
  std::merge(knots.begin(), knots.end(), new_knots.begin(), new_knots.end(), std::back_inserter(out));
  return out;
}

}  // namespace

NurbsCurve refine_knots(const NurbsCurve& curve, const std::vector<double>& new_knots) {
  if (new_knots.empty()) return curve;
  check_refinement(curve.knots, curve.order, curve.count(), new_knots);
  HomogeneousRow row = to_homogeneous(curve.points, curve.weights);
  NurbsCurve out = curve;
  out.knots = merged_knots(curve.knots, new_knots);
  refine_row(curve.knots, out.knots, curve.order, new_knots, row);
  from_homogeneous(row, curve.is_rational(), out.points, out.weights);
  if (curve.dimension == 2)
    for (auto& p : out.points) p.z() = 0.0;
  return out;
}

NurbsSurface refine_knots(const NurbsSurface& s, SurfaceDirection direction, const std::vector<double>& new_knots) {
  if (new_knots.empty()) return s;
  const bool in_u = direction == SurfaceDirection::u;
  const auto& knots = in_u ? s.u_knots : s.v_knots;
  const int order = in_u ? s.u_order : s.v_order;
  const int count = in_u ? s.u_count : s.v_count;
  check_refinement(knots, order, count, new_knots);
  const std::vector<double> refined_knots = merged_knots(knots, new_knots);
  return rewrite_rows(s, direction, count + static_cast<int>(new_knots.size()), refined_knots, [&](HomogeneousRow row) {
    refine_row(knots, refined_knots, order, new_knots, row);
    return row;
  });
}

}  // namespace cadnurbs
