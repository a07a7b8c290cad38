#include "formats/brep/occt_to_nurbs.hpp"

#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <TColgp_Array2OfPnt.hxx>

namespace cadnurbs {

namespace {

// Whether the first and the last `degree + 1` flat knots are equal: a clamped B-spline starts and ends at
// its end control points.
bool clamped(const TColStd_Array1OfReal& flat, int degree) {
  for (int i = 1; i <= degree; ++i)
    if (flat(flat.Lower() + i) != flat(flat.Lower()) || flat(flat.Upper() - i) != flat(flat.Upper())) return false;
  return true;
}

std::vector<double> flat_knots(const TColStd_Array1OfReal& sequence) {
  std::vector<double> out;
  out.reserve(sequence.Length());
  for (int i = sequence.Lower(); i <= sequence.Upper(); ++i) out.push_back(sequence(i));
  return out;
}

}  // namespace

NurbsSurface to_nurbs_surface(const Handle(Geom_BSplineSurface)& input) {
  Handle(Geom_BSplineSurface) surface = input;
  if (surface->IsUPeriodic() || surface->IsVPeriodic() || !clamped(surface->UKnotSequence(), surface->UDegree()) ||
      !clamped(surface->VKnotSequence(), surface->VDegree())) {
    // Unperiodizing keeps the parameters but may leave unclamped ends (OCCT allows them); segmenting to
    // the surface's own bounds clamps them, same geometry. The copy leaves the caller's surface alone.
    surface = Handle(Geom_BSplineSurface)::DownCast(input->Copy());
    if (surface->IsUPeriodic()) surface->SetUNotPeriodic();
    if (surface->IsVPeriodic()) surface->SetVNotPeriodic();
    if (!clamped(surface->UKnotSequence(), surface->UDegree()) || !clamped(surface->VKnotSequence(), surface->VDegree())) {
      Standard_Real u0, u1, v0, v1;
      surface->Bounds(u0, u1, v0, v1);
      surface->Segment(u0, u1, v0, v1);
    }
  }
  NurbsSurface out;
  out.u_order = surface->UDegree() + 1;
  out.v_order = surface->VDegree() + 1;
  out.u_count = surface->NbUPoles();
  out.v_count = surface->NbVPoles();
  out.u_knots = flat_knots(surface->UKnotSequence());
  out.v_knots = flat_knots(surface->VKnotSequence());
  const TColgp_Array2OfPnt& poles = surface->Poles();
  const bool rational = surface->IsURational() || surface->IsVRational();
  const TColStd_Array2OfReal* weights = rational ? surface->Weights() : nullptr;
  out.points.reserve(static_cast<size_t>(out.u_count) * out.v_count);
  for (int j = 0; j < out.v_count; ++j)
    for (int i = 0; i < out.u_count; ++i) {
      const gp_Pnt& p = poles(poles.LowerRow() + i, poles.LowerCol() + j);
      out.points.emplace_back(p.X(), p.Y(), p.Z());
      if (weights) out.weights.push_back((*weights)(weights->LowerRow() + i, weights->LowerCol() + j));
    }
  return out;
}

NurbsCurve to_nurbs_curve_2d(const Handle(Geom2d_BSplineCurve)& input) {
  Handle(Geom2d_BSplineCurve) curve = input;
  if (curve->IsPeriodic() || !clamped(curve->KnotSequence(), curve->Degree())) {
    curve = Handle(Geom2d_BSplineCurve)::DownCast(input->Copy());
    if (curve->IsPeriodic()) curve->SetNotPeriodic();
    if (!clamped(curve->KnotSequence(), curve->Degree())) curve->Segment(curve->FirstParameter(), curve->LastParameter());
  }
  NurbsCurve out;
  out.dimension = 2;
  out.order = curve->Degree() + 1;
  out.knots = flat_knots(curve->KnotSequence());
  const TColgp_Array1OfPnt2d& poles = curve->Poles();
  for (int i = poles.Lower(); i <= poles.Upper(); ++i) out.points.emplace_back(poles(i).X(), poles(i).Y(), 0.0);
  if (curve->IsRational())
    for (int i = 1; i <= curve->NbPoles(); ++i) out.weights.push_back(curve->Weight(i));
  return out;
}

}  // namespace cadnurbs
