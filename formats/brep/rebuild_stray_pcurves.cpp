#include "formats/brep/rebuild_stray_pcurves.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_Curve.hxx>
#include <Precision.hxx>
#include <ShapeAnalysis_Curve.hxx>
#include <ShapeAnalysis_Surface.hxx>
#include <ShapeFix_Edge.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <algorithm>

#include "core/number_format.hpp"

namespace cadnurbs {

namespace {

constexpr int kSamples = 33;

// How far the edge's 3D curve lies from the face's surface (33 samples): where it is itself off the
// surface, a model gap rather than a stray pcurve, no projection can bring the two together.
double curve_to_surface_distance(const TopoDS_Edge& edge, const TopoDS_Face& face) {
  TopLoc_Location location;
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(face, location);
  ShapeAnalysis_Surface analysis(surface);
  const gp_Trsf to_surface = location.Transformation().Inverted();
  const BRepAdaptor_Curve curve(edge);
  double largest = 0.0;
  for (int i = 0; i < kSamples; ++i) {
    const double t = curve.FirstParameter() + (curve.LastParameter() - curve.FirstParameter()) * i / (kSamples - 1);
    analysis.ValueOfUV(curve.Value(t).Transformed(to_surface), Precision::Confusion());
    largest = std::max(largest, analysis.Gap());
  }
  return largest;
}

}  // namespace

double pcurve_stray_distance(const TopoDS_Edge& edge, const TopoDS_Face& face) {
  if (BRep_Tool::Degenerated(edge) || !BRep_Tool::IsGeometric(edge)) return 0.0;
  double first = 0, last = 0;
  if (BRep_Tool::CurveOnSurface(edge, face, first, last).IsNull()) return 0.0;
  const BRepAdaptor_Curve curve(edge);            // the 3D curve, placed
  const BRepAdaptor_Curve on_surface(edge, face);  // S(pcurve(t)), placed
  const ShapeAnalysis_Curve analysis;
  double largest = 0.0;
  for (int i = 0; i < kSamples; ++i) {
    const double t = first + (last - first) * i / (kSamples - 1);
    gp_Pnt nearest;
    double parameter = 0;
    largest = std::max(largest, analysis.Project(curve, on_surface.Value(t), Precision::Confusion(), nearest, parameter));
  }
  return largest;
}

std::vector<std::string> rebuild_stray_pcurves(const TopoDS_Face& face, double limit,
                                               const std::function<int(const TopoDS_Edge&)>& edge_number) {
  std::vector<std::string> lines;
  for (TopExp_Explorer edges(face, TopAbs_EDGE); edges.More(); edges.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(edges.Current());
    if (BRep_Tool::IsClosed(edge, face)) continue;  // a seam: two pcurves, one edge; left to NurbsConvert
    const double before = pcurve_stray_distance(edge, face);
    if (before <= std::max(limit, BRep_Tool::Tolerance(edge))) continue;
    if (curve_to_surface_distance(edge, face) > limit) continue;  // a model gap: sewing's concern
    const std::string name = "pcurve of edge " + std::to_string(edge_number(edge));
    double first = 0, last = 0;
    const Handle(Geom2d_Curve) old_pcurve = BRep_Tool::CurveOnSurface(edge, face, first, last);
    ShapeFix_Edge fix;
    fix.FixRemovePCurve(edge, face);
    fix.FixAddPCurve(edge, face, /*isSeam=*/false);
    const double after = pcurve_stray_distance(edge, face);
    double new_first = 0, new_last = 0;
    const bool made = !BRep_Tool::CurveOnSurface(edge, face, new_first, new_last).IsNull();
    if (made && after < before && after <= limit) {
      lines.push_back(name + " was " + message_number(before) + " from its 3D curve: rebuilt from it (now " +
                      message_number(after) + ")");
      continue;
    }
    // No better: the old pcurve goes back.
    BRep_Builder().UpdateEdge(edge, old_pcurve, face, BRep_Tool::Tolerance(edge));
    BRep_Builder().Range(edge, face, first, last);
    lines.push_back(name + " is " + message_number(before) + " from its 3D curve: left (no better projection)");
  }
  return lines;
}

}  // namespace cadnurbs
