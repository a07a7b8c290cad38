#include "formats/brep/direct_face.hpp"

#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Bnd_Box2d.hxx>
#include <Convert_TorusToBSplineSurface.hxx>
#include <Geom2d_BezierCurve.hxx>
#include <Geom2d_Line.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <GeomConvert.hxx>
#include <Geom_BezierSurface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_ConicalSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_Plane.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_SphericalSurface.hxx>
#include <Geom_SurfaceOfLinearExtrusion.hxx>
#include <Geom_SurfaceOfRevolution.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <gp_Torus.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <Precision.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <algorithm>
#include <cmath>
#include <functional>

namespace cadnurbs {

namespace {

// Thrown inside when the fast path does not apply; the caller falls back to NurbsConvert.
struct NotAnalytic {};

bool supported(const Handle(Geom_Surface)& s) {
  return s->IsKind(STANDARD_TYPE(Geom_Plane)) || s->IsKind(STANDARD_TYPE(Geom_CylindricalSurface)) ||
         s->IsKind(STANDARD_TYPE(Geom_ConicalSurface)) || s->IsKind(STANDARD_TYPE(Geom_SphericalSurface)) ||
         s->IsKind(STANDARD_TYPE(Geom_ToroidalSurface)) || s->IsKind(STANDARD_TYPE(Geom_SurfaceOfRevolution)) ||
         s->IsKind(STANDARD_TYPE(Geom_SurfaceOfLinearExtrusion));
}

// From one parameter of the analytic surface to the same parameter of its B-spline conversion, along an
// iso-curve of the B-spline: start and end of the range map to the ends of the B-spline's domain, points
// between to the foot of the perpendicular (Newton from the nearest of 33 samples), which must be within
// `tolerance` of the analytic point.
class ParameterMap {
 public:
  ParameterMap(std::function<gp_Pnt(double)> analytic, Handle(Geom_Curve) iso, double a, double b, double s0, double s1,
               double tolerance)
      : analytic_(std::move(analytic)), iso_(std::move(iso)), a_(a), b_(b), s0_(s0), s1_(s1), tolerance_(tolerance) {
    // Off-centre samples: a quasi-angular conversion agrees with the angle at the ends and middles
    // of its spans (Ventilator.stp's half cylinders passed a 5-point test, 1.6 mm off in between).
    identity_ = true;
    for (int k = 0; k < 24 && identity_; ++k) {
      const double x = a_ + (b_ - a_) * (k + 0.3) / 24;
      identity_ = std::abs((*this)(x) - x) <= 1e-12 * std::max(1.0, std::abs(b_ - a_));
    }
  }

  bool identity() const { return identity_; }

  double operator()(double x) const {
    const double span = b_ - a_, eps = 1e-9 * span;
    if (std::abs(x - a_) <= eps) return s0_;
    if (std::abs(x - b_) <= eps) return s1_;
    if (x < a_ - eps || x > b_ + eps) throw NotAnalytic{};
    const gp_Pnt target = analytic_(x);
    // Start from the nearest of a few samples: the map is monotone but may bend far from proportional.
    double s = s0_, nearest = Precision::Infinite();
    for (int i = 0; i <= 32; ++i) {
      const double candidate = s0_ + (s1_ - s0_) * i / 32;
      const double d = iso_->Value(candidate).SquareDistance(target);
      if (d < nearest) nearest = d, s = candidate;
    }
    for (int i = 0; i < 50; ++i) {
      gp_Pnt p;
      gp_Vec d1, d2;
      iso_->D2(s, p, d1, d2);
      const gp_Vec r(target, p);
      // Newton on f(s) = r . d1 = 0, the foot of the perpendicular.
      const double f = r.Dot(d1), df = d1.SquareMagnitude() + r.Dot(d2);
      if (df <= 0) throw NotAnalytic{};
      const double next = std::clamp(s - f / df, std::min(s0_, s1_), std::max(s0_, s1_));
      const bool done = std::abs(next - s) <= 1e-15 * std::abs(s1_ - s0_);
      s = next;
      if (done) break;
    }
    if (iso_->Value(s).Distance(target) > tolerance_) throw NotAnalytic{};
    return s;
  }

 private:
  std::function<gp_Pnt(double)> analytic_;
  Handle(Geom_Curve) iso_;
  double a_, b_, s0_, s1_, tolerance_;
  bool identity_ = false;
};

// Whether the pcurve runs along one iso-line (u constant: 1, v constant: 0), monotonically; -1 otherwise.
int iso_direction(const Handle(Geom2d_Curve)& pcurve) {
  Handle(Geom2d_Curve) curve = pcurve;
  while (auto t = Handle(Geom2d_TrimmedCurve)::DownCast(curve)) curve = t->BasisCurve();
  if (auto line = Handle(Geom2d_Line)::DownCast(curve)) {
    const gp_Dir2d d = line->Direction();
    if (std::abs(d.Y()) <= 1e-12) return 0;
    if (std::abs(d.X()) <= 1e-12) return 1;
    return -1;
  }
  // B-splines from STEP or IGES often carry straight iso-lines as degree-1 or higher curves.
  TColgp_Array1OfPnt2d poles(1, 1);
  if (auto bspline = Handle(Geom2d_BSplineCurve)::DownCast(curve)) {
    poles.Resize(1, bspline->NbPoles(), false);
    bspline->Poles(poles);
  } else if (auto bezier = Handle(Geom2d_BezierCurve)::DownCast(curve)) {
    poles.Resize(1, bezier->NbPoles(), false);
    bezier->Poles(poles);
  } else {
    return -1;
  }
  for (int direction = 0; direction < 2; ++direction) {
    auto fixed = [&](int i) { return direction == 0 ? poles(i).Y() : poles(i).X(); };
    auto moving = [&](int i) { return direction == 0 ? poles(i).X() : poles(i).Y(); };
    const double scale = std::max(1.0, std::abs(moving(poles.Lower())) + std::abs(moving(poles.Upper())));
    bool on_line = true, increasing = true, decreasing = true;
    for (int i = poles.Lower() + 1; i <= poles.Upper(); ++i) {
      on_line = on_line && std::abs(fixed(i) - fixed(poles.Lower())) <= 1e-12 * scale;
      increasing = increasing && moving(i) >= moving(i - 1);
      decreasing = decreasing && moving(i) <= moving(i - 1);
    }
    if (on_line && (increasing || decreasing)) return direction;
  }
  return -1;
}

Handle(Geom2d_BSplineCurve) segment(const gp_Pnt2d& from, const gp_Pnt2d& to, double first, double last) {
  TColgp_Array1OfPnt2d poles(1, 2);
  poles(1) = from;
  poles(2) = to;
  TColStd_Array1OfReal knots(1, 2);
  knots(1) = first;
  knots(2) = last;
  TColStd_Array1OfInteger multiplicities(1, 2);
  multiplicities.Init(2);
  return new Geom2d_BSplineCurve(poles, knots, multiplicities, 1);
}

// The (u,v) box of the face's pcurves, from samples. BRepTools::UVBounds and ShapeAnalysis give a box
// that may sit off the face's own seam by a few hundredths on full cylinders (11752.stp), which leaves
// a sliver of the face outside one period.
void face_uv_bounds(const TopoDS_Face& face, double& u0, double& u1, double& v0, double& v1) {
  Bnd_Box2d box;
  for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next()) {
    Standard_Real first, last;
    const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(TopoDS::Edge(ex.Current()), face, first, last);
    if (pcurve.IsNull()) continue;
    for (int i = 0; i <= 64; ++i) box.Add(pcurve->Value(first + (last - first) * i / 64));
  }
  if (box.IsVoid()) {
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    return;
  }
  box.SetGap(0);
  box.Get(u0, v0, u1, v1);
}

// The end of a range starting at `a` and ending at `b` or one period later, whichever comes first, such
// that end - a <= period in floating point too (a + period may round up): OCCT's converters refuse a
// range longer than 2 pi, even by a rounding error.
double within_one_period(double a, double b, double period) {
  double end = std::min(b, a + period);
  while (end - a > period) end = std::nextafter(end, a);
  return end;
}

// The analytic surface over [u0, u1] x [v0, v1] as a B-spline (GeomConvert), a torus straight through
// Convert_TorusToBSplineSurface: a Geom_RectangularTrimmedSurface moves a range into [0, 2 pi) and may
// make it one rounding error longer than 2 pi (v from -3.141592653589794 to 3.1415926535897922 came out
// as 3.1415926535897922 to 9.4247779607693793), which the converter refuses.
Handle(Geom_BSplineSurface) analytic_bspline(const Handle(Geom_Surface)& basis, double u0, double u1, double v0,
                                             double v1) {
  auto torus = Handle(Geom_ToroidalSurface)::DownCast(basis);
  if (torus.IsNull())
    return GeomConvert::SurfaceToBSplineSurface(new Geom_RectangularTrimmedSurface(basis, u0, u1, v0, v1));
  const Convert_TorusToBSplineSurface convert(torus->Torus(), u0, u1, v0, v1);
  TColgp_Array2OfPnt poles(1, convert.NbUPoles(), 1, convert.NbVPoles());
  TColStd_Array2OfReal weights(1, convert.NbUPoles(), 1, convert.NbVPoles());
  for (int i = 1; i <= convert.NbUPoles(); ++i)
    for (int j = 1; j <= convert.NbVPoles(); ++j) {
      poles(i, j) = convert.Pole(i, j);
      weights(i, j) = convert.Weight(i, j);
    }
  TColStd_Array1OfReal u_knots(1, convert.NbUKnots()), v_knots(1, convert.NbVKnots());
  TColStd_Array1OfInteger u_mults(1, convert.NbUKnots()), v_mults(1, convert.NbVKnots());
  for (int i = 1; i <= convert.NbUKnots(); ++i) u_knots(i) = convert.UKnot(i), u_mults(i) = convert.UMultiplicity(i);
  for (int j = 1; j <= convert.NbVKnots(); ++j) v_knots(j) = convert.VKnot(j), v_mults(j) = convert.VMultiplicity(j);
  return new Geom_BSplineSurface(poles, weights, u_knots, v_knots, u_mults, v_mults, convert.UDegree(), convert.VDegree());
}

}  // namespace

std::optional<BSplineFace> direct_face(const TopoDS_Face& face, EdgeNumbering& edges) {
  Handle(Geom_Surface) basis = BRep_Tool::Surface(face);  // location applied
  if (basis.IsNull()) return std::nullopt;
  while (auto trimmed = Handle(Geom_RectangularTrimmedSurface)::DownCast(basis)) basis = trimmed->BasisSurface();
  const TopoDS_Face forward = TopoDS::Face(face.Oriented(TopAbs_FORWARD));
  auto number = [&](const TopoDS_Edge& edge) { return edges.number(edge); };

  // B-splines and Bezier patches keep their parameters: nothing to map.
  if (auto bspline = Handle(Geom_BSplineSurface)::DownCast(basis)) {
    BSplineFace out;
    out.surface = Handle(Geom_BSplineSurface)::DownCast(bspline->Copy());
    out.wires = face_pcurves(forward, number, trimmed_bspline);
    return out;
  }
  if (basis->IsKind(STANDARD_TYPE(Geom_BezierSurface))) {
    BSplineFace out;
    out.surface = GeomConvert::SurfaceToBSplineSurface(basis);
    out.wires = face_pcurves(forward, number, trimmed_bspline);
    return out;
  }
  if (!supported(basis)) return std::nullopt;

  // The face's range, within the surface's bounds and at most one period, as NurbsConvert takes it.
  Standard_Real u0, u1, v0, v1, su0, su1, sv0, sv1;
  face_uv_bounds(face, u0, u1, v0, v1);
  basis->Bounds(su0, su1, sv0, sv1);
  if (!basis->IsUPeriodic()) u0 = std::max(u0, su0), u1 = std::min(u1, su1);
  else u1 = within_one_period(u0, u1, basis->UPeriod());
  if (!basis->IsVPeriodic()) v0 = std::max(v0, sv0), v1 = std::min(v1, sv1);
  else v1 = within_one_period(v0, v1, basis->VPeriod());
  if (!(u1 > u0) || !(v1 > v0)) return std::nullopt;

  BSplineFace out;
  out.surface = analytic_bspline(basis, u0, u1, v0, v1);
  Standard_Real s0, s1, t0, t1;
  out.surface->Bounds(s0, s1, t0, t1);
  // The face's size, from a 5 x 5 grid of its surface: mapped points must agree to 1e-9 of it.
  Bnd_Box box;
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 4; ++j) box.Add(basis->Value(u0 + (u1 - u0) * i / 4, v0 + (v1 - v0) * j / 4));
  const double tolerance = std::max(1e-9 * std::sqrt(box.SquareExtent()), 1e-12);
  // The conversion must start and end where the face's range does (a periodic result may start elsewhere).
  for (double u : {u0, u1})
    for (double v : {v0, v1}) {
      const double s = u == u0 ? s0 : s1, t = v == v0 ? t0 : t1;
      if (out.surface->Value(s, t).Distance(basis->Value(u, v)) > tolerance) return std::nullopt;
    }

  // Iso-curves of the B-spline through the middle of the face, where no pole is.
  const double um = 0.5 * (u0 + u1), vm = 0.5 * (v0 + v1);
  try {
    // The B-spline's v of the face's middle: along any u iso-curve of these surfaces the nearest point to a
    // point of latitude (height) v has the same v, so the middle iso-curve finds it without knowing u yet.
    // (The point is not on that iso-curve, only level with it: no distance limit here.)
    const ParameterMap v_middle([&](double v) { return basis->Value(um, v); }, out.surface->UIso(0.5 * (s0 + s1)), v0, v1,
                                t0, t1, Precision::Infinite());
    const double tm = v_middle(vm);
    const ParameterMap u_map([&](double u) { return basis->Value(u, vm); }, out.surface->VIso(tm), u0, u1, s0, s1,
                             tolerance);
    const double sm = u_map(um);
    const ParameterMap v_map([&](double v) { return basis->Value(um, v); }, out.surface->UIso(sm), v0, v1, t0, t1,
                             tolerance);
    const bool keeps_both = u_map.identity() && v_map.identity();

    auto to_bspline = [&](const Handle(Geom2d_Curve)& pcurve, double first, double last) -> Handle(Geom2d_BSplineCurve) {
      if (keeps_both) return trimmed_bspline(pcurve, first, last);
      if (iso_direction(pcurve) < 0) throw NotAnalytic{};
      const gp_Pnt2d a = pcurve->Value(first), b = pcurve->Value(last);
      const gp_Pnt2d ma(u_map(a.X()), v_map(a.Y())), mb(u_map(b.X()), v_map(b.Y()));
      // The mapped ends must be the same 3D points.
      if (out.surface->Value(ma.X(), ma.Y()).Distance(basis->Value(a.X(), a.Y())) > tolerance ||
          out.surface->Value(mb.X(), mb.Y()).Distance(basis->Value(b.X(), b.Y())) > tolerance)
        throw NotAnalytic{};
      return segment(ma, mb, first, last);
    };
    out.wires = face_pcurves(forward, number, to_bspline);
  } catch (const NotAnalytic&) {
    return std::nullopt;
  }
  return out;
}

}  // namespace cadnurbs
