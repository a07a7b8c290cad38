#include "formats/brep/nurbs_to_occt.hpp"

#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <cmath>
#include <limits>

#include "core/geometry_error.hpp"

namespace cadnurbs {

namespace {

// Distinct knots and multiplicities of a flat knot vector, as OCCT wants them. Values equal to a few
// units in the last place count as one knot: OCCT refuses knots closer than that.
struct OcctKnots {
  TColStd_Array1OfReal knots;
  TColStd_Array1OfInteger multiplicities;
};

OcctKnots occt_knots(const std::vector<double>& flat, int order, const std::string& entity, const char* direction) {
  std::vector<double> values;
  std::vector<int> counts;
  for (double k : flat) {
    const double eps = 4 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(k));
    if (!values.empty() && k - values.back() <= eps) {
      ++counts.back();
    } else {
      values.push_back(k);
      counts.push_back(1);
    }
  }
  for (size_t i = 1; i + 1 < counts.size(); ++i)
    if (counts[i] >= order)
      throw GeometryError(entity, std::string(direction) + "knot " + std::to_string(values[i]) + " is repeated " +
                                      std::to_string(counts[i]) + " times: a discontinuous B-spline, which OCCT cannot hold");
  OcctKnots out{TColStd_Array1OfReal(1, static_cast<int>(values.size())),
                TColStd_Array1OfInteger(1, static_cast<int>(values.size()))};
  for (size_t i = 0; i < values.size(); ++i) {
    out.knots(static_cast<int>(i) + 1) = values[i];
    out.multiplicities(static_cast<int>(i) + 1) = counts[i];
  }
  return out;
}

Handle(Geom2d_BSplineCurve) polyline_curve(const Polyline2D& polyline) {
  const int n = static_cast<int>(polyline.points.size());
  TColgp_Array1OfPnt2d poles(1, n);
  TColStd_Array1OfReal knots(1, n);
  TColStd_Array1OfInteger multiplicities(1, n);
  double length = 0;
  for (int i = 0; i < n; ++i) {
    if (i > 0) {
      const double step = (polyline.points[i] - polyline.points[i - 1]).norm();
      // A repeated point would repeat a knot; keep the parameter increasing.
      length += step > 0 ? step : 1e-12 * std::max(1.0, length);
    }
    poles(i + 1) = gp_Pnt2d(polyline.points[i].x(), polyline.points[i].y());
    knots(i + 1) = length;
    multiplicities(i + 1) = (i == 0 || i == n - 1) ? 2 : 1;
  }
  return new Geom2d_BSplineCurve(poles, knots, multiplicities, 1);
}

}  // namespace

Handle(Geom_BSplineSurface) to_occt_surface(const NurbsSurface& surface, const std::string& entity) {
  validate(surface, entity);
  OcctKnots u = occt_knots(surface.u_knots, surface.u_order, entity, "u ");
  OcctKnots v = occt_knots(surface.v_knots, surface.v_order, entity, "v ");
  TColgp_Array2OfPnt poles(1, surface.u_count, 1, surface.v_count);
  TColStd_Array2OfReal weights(1, surface.u_count, 1, surface.v_count);
  for (int j = 0; j < surface.v_count; ++j)
    for (int i = 0; i < surface.u_count; ++i) {
      const Eigen::Vector3d& p = surface.point(i, j);
      poles(i + 1, j + 1) = gp_Pnt(p.x(), p.y(), p.z());
      weights(i + 1, j + 1) = surface.weight(i, j);
    }
  if (surface.is_rational())
    return new Geom_BSplineSurface(poles, weights, u.knots, v.knots, u.multiplicities, v.multiplicities,
                                   surface.u_order - 1, surface.v_order - 1);
  return new Geom_BSplineSurface(poles, u.knots, v.knots, u.multiplicities, v.multiplicities, surface.u_order - 1,
                                 surface.v_order - 1);
}

Handle(Geom_BSplineCurve) to_occt_curve(const NurbsCurve& curve, const std::string& entity) {
  validate(curve, entity);
  OcctKnots k = occt_knots(curve.knots, curve.order, entity, "");
  TColgp_Array1OfPnt poles(1, curve.count());
  TColStd_Array1OfReal weights(1, curve.count());
  for (int i = 0; i < curve.count(); ++i) {
    poles(i + 1) = gp_Pnt(curve.points[i].x(), curve.points[i].y(), curve.points[i].z());
    weights(i + 1) = curve.weight(i);
  }
  if (curve.is_rational()) return new Geom_BSplineCurve(poles, weights, k.knots, k.multiplicities, curve.order - 1);
  return new Geom_BSplineCurve(poles, k.knots, k.multiplicities, curve.order - 1);
}

Handle(Geom2d_BSplineCurve) to_occt_curve_2d(const TrimSegment& segment, const std::string& entity) {
  if (const auto* polyline = std::get_if<Polyline2D>(&segment)) {
    if (polyline->points.size() < 2) throw GeometryError(entity, "polyline has fewer than 2 points");
    return polyline_curve(*polyline);
  }
  const NurbsCurve& curve = std::get<NurbsCurve>(segment);
  validate(curve, entity);
  if (curve.dimension != 2) throw GeometryError(entity, "trimming curve is not 2D");
  OcctKnots k = occt_knots(curve.knots, curve.order, entity, "");
  TColgp_Array1OfPnt2d poles(1, curve.count());
  TColStd_Array1OfReal weights(1, curve.count());
  for (int i = 0; i < curve.count(); ++i) {
    poles(i + 1) = gp_Pnt2d(curve.points[i].x(), curve.points[i].y());
    weights(i + 1) = curve.weight(i);
  }
  if (curve.is_rational()) return new Geom2d_BSplineCurve(poles, weights, k.knots, k.multiplicities, curve.order - 1);
  return new Geom2d_BSplineCurve(poles, k.knots, k.multiplicities, curve.order - 1);
}

}  // namespace cadnurbs
