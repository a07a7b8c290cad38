#include "core/knot_insertion.hpp"

#include <algorithm>
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
  const int other = in_u ? s.v_count : s.u_count;
  const auto place = check_insertion(knots, order, count, t, times);

  NurbsSurface out = s;
  (in_u ? out.u_count : out.v_count) = count + times;
  (in_u ? out.u_knots : out.v_knots) = inserted_knots(knots, t, times, place.span);
  out.points.assign(static_cast<size_t>(out.u_count) * out.v_count, Eigen::Vector3d::Zero());
  if (s.is_rational()) out.weights.assign(out.points.size(), 1.0);
  for (int r = 0; r < other; ++r) {
    HomogeneousRow row(count);
    for (int c = 0; c < count; ++c) {
      const int i = in_u ? c : r, j = in_u ? r : c;
      row[c] << s.weight(i, j) * s.point(i, j), s.weight(i, j);
    }
    const auto refined = insert_into_row(knots, order, row, t, times, place.span, place.multiplicity);
    for (int c = 0; c < count + times; ++c) {
      const int i = in_u ? c : r, j = in_u ? r : c;
      out.points[out.index(i, j)] = refined[c].head<3>() / refined[c][3];
      if (s.is_rational()) out.weights[out.index(i, j)] = refined[c][3];
    }
  }
  return out;
}

NurbsCurve refine_knots(const NurbsCurve& curve, const std::vector<double>& new_knots) {
  NurbsCurve out = curve;
  for (double t : new_knots) out = insert_knot(out, t, 1);
  return out;
}

NurbsSurface refine_knots(const NurbsSurface& surface, SurfaceDirection direction,
                          const std::vector<double>& new_knots) {
  NurbsSurface out = surface;
  for (double t : new_knots) out = insert_knot(out, direction, t, 1);
  return out;
}

}  // namespace cadnurbs
