#include "formats/brep/face_mesh_guard.hpp"

#include <BRepBndLib.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace cadnurbs {

namespace {

bool within_reach(double value) { return std::abs(value) <= max_mesh_coordinate; }  // false for NaN

// "" or what is wrong with a set of weights.
std::string weights_problem(const std::vector<double>& weights, const char* owner) {
  double smallest = HUGE_VAL, largest = 0;
  for (const double w : weights) {
    if (!(w > 0) || !std::isfinite(w)) return std::string(owner) + " has a weight that is not a positive number";
    smallest = std::min(smallest, w);
    largest = std::max(largest, w);
  }
  if (largest > smallest * max_weight_ratio) {
    char range[64];
    std::snprintf(range, sizeof range, "%.3g to %.3g", smallest, largest);
    return std::string(owner) + " has weights spread by more than 1e10 (" + range + ")";
  }
  return "";
}

std::string surface_problem(Handle(Geom_Surface) surface) {
  if (auto trimmed = Handle(Geom_RectangularTrimmedSurface)::DownCast(surface)) surface = trimmed->BasisSurface();
  const auto bspline = Handle(Geom_BSplineSurface)::DownCast(surface);
  if (bspline.IsNull()) return "";
  for (int i = 1; i <= bspline->NbUPoles(); ++i)
    for (int j = 1; j <= bspline->NbVPoles(); ++j) {
      const gp_Pnt p = bspline->Pole(i, j);
      if (!within_reach(p.X()) || !within_reach(p.Y()) || !within_reach(p.Z()))
        return "its surface has a control point beyond ±1e15";
    }
  if (!bspline->IsURational() && !bspline->IsVRational()) return "";
  std::vector<double> weights;
  for (int i = 1; i <= bspline->NbUPoles(); ++i)
    for (int j = 1; j <= bspline->NbVPoles(); ++j) weights.push_back(bspline->Weight(i, j));
  return weights_problem(weights, "its surface");
  return "";
}

std::string pcurve_problem(Handle(Geom2d_Curve) curve) {
  if (auto trimmed = Handle(Geom2d_TrimmedCurve)::DownCast(curve)) curve = trimmed->BasisCurve();
  const auto bspline = Handle(Geom2d_BSplineCurve)::DownCast(curve);
  if (bspline.IsNull()) return "";
  for (int i = 1; i <= bspline->NbPoles(); ++i) {
    const gp_Pnt2d p = bspline->Pole(i);
    if (!within_reach(p.X()) || !within_reach(p.Y())) return "a pcurve has a control point beyond ±1e15";
  }
  if (!bspline->IsRational()) return "";
  std::vector<double> weights;
  for (int i = 1; i <= bspline->NbPoles(); ++i) weights.push_back(bspline->Weight(i));
  return weights_problem(weights, "a pcurve");
}

}  // namespace

std::string why_not_meshable(const TopoDS_Face& face) {
  Bnd_Box box;
  BRepBndLib::Add(face, box, /*useTriangulation=*/false);
  if (!box.IsVoid()) {
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    for (const double c : {x0, y0, z0, x1, y1, z1})
      if (!within_reach(c)) return "it reaches beyond ±1e15 model units";
  }
  if (std::string problem = surface_problem(BRep_Tool::Surface(face)); !problem.empty()) return problem;
  for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next()) {
    double first, last;
    const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(TopoDS::Edge(ex.Current()), face, first, last);
    if (pcurve.IsNull()) continue;
    if (std::string problem = pcurve_problem(pcurve); !problem.empty()) return problem;
  }
  return "";
}

}  // namespace cadnurbs
