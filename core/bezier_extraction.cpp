#include "core/bezier_extraction.hpp"

#include <algorithm>

#include "core/knot_insertion.hpp"
#include "core/knot_vector.hpp"

namespace cadnurbs {

namespace {

// Interior knot values of the domain and how many more copies each needs to reach `degree` copies.
std::vector<double> knots_to_saturate(const std::vector<double>& knots, int order, int count) {
  std::vector<double> extra;
  const double a = knots[order - 1], b = knots[count];
  for (const auto& km : knot_multiplicities(knots))
    if (km.value > a && km.value < b)
      for (int m = km.multiplicity; m < order - 1; ++m) extra.push_back(km.value);
  return extra;
}

// Start indices (into the saturated knot vector) of the first control point of each Bézier piece.
std::vector<std::pair<double, double>> spans(const std::vector<double>& knots, int order, int count) {
  std::vector<std::pair<double, double>> out;
  for (int i = order - 1; i < count; ++i)
    if (knots[i] < knots[i + 1]) out.emplace_back(knots[i], knots[i + 1]);
  return out;
}

std::vector<double> bezier_knots(int order, double a, double b) {
  std::vector<double> k(order, a);
  k.insert(k.end(), order, b);
  return k;
}

}  // namespace

std::vector<NurbsCurve> bezier_segments(const NurbsCurve& curve) {
  const NurbsCurve full = refine_knots(curve, knots_to_saturate(curve.knots, curve.order, curve.count()));
  std::vector<NurbsCurve> out;
  const int p = curve.degree();
  int first = 0;  // first control point of the current piece
  for (const auto& [a, b] : spans(full.knots, full.order, full.count())) {
    NurbsCurve piece;
    piece.dimension = curve.dimension;
    piece.order = curve.order;
    piece.knots = bezier_knots(curve.order, a, b);
    // The piece over [a, b] uses the control points whose span ends at b.
    const int span = find_knot_span(full.knots, full.order, full.count(), 0.5 * (a + b));
    first = span - p;
    piece.points.assign(full.points.begin() + first, full.points.begin() + first + curve.order);
    if (full.is_rational()) piece.weights.assign(full.weights.begin() + first, full.weights.begin() + first + curve.order);
    out.push_back(std::move(piece));
  }
  return out;
}

std::vector<NurbsSurface> bezier_patches(const NurbsSurface& surface) {
  NurbsSurface full =
      refine_knots(surface, SurfaceDirection::u, knots_to_saturate(surface.u_knots, surface.u_order, surface.u_count));
  full = refine_knots(full, SurfaceDirection::v, knots_to_saturate(full.v_knots, full.v_order, full.v_count));
  std::vector<NurbsSurface> out;
  const auto uspans = spans(full.u_knots, full.u_order, full.u_count);
  const auto vspans = spans(full.v_knots, full.v_order, full.v_count);
  for (const auto& [va, vb] : vspans) {
    const int j0 = find_knot_span(full.v_knots, full.v_order, full.v_count, 0.5 * (va + vb)) - (full.v_order - 1);
    for (const auto& [ua, ub] : uspans) {
      const int i0 = find_knot_span(full.u_knots, full.u_order, full.u_count, 0.5 * (ua + ub)) - (full.u_order - 1);
      NurbsSurface patch;
      patch.u_order = full.u_order;
      patch.v_order = full.v_order;
      patch.u_count = full.u_order;
      patch.v_count = full.v_order;
      patch.u_knots = bezier_knots(full.u_order, ua, ub);
      patch.v_knots = bezier_knots(full.v_order, va, vb);
      for (int j = 0; j < full.v_order; ++j)
        for (int i = 0; i < full.u_order; ++i) {
          patch.points.push_back(full.point(i0 + i, j0 + j));
          if (full.is_rational()) patch.weights.push_back(full.weight(i0 + i, j0 + j));
        }
      out.push_back(std::move(patch));
    }
  }
  return out;
}

}  // namespace cadnurbs
