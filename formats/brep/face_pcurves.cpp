#include "formats/brep/face_pcurves.hpp"

#include <BRep_Tool.hxx>
#include <Geom2dConvert.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <Precision.hxx>
#include <TopExp.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>

#include "formats/brep/face_to_trimmed_surface.hpp"
#include "formats/brep/wire_order.hpp"

namespace cadnurbs {

Handle(Geom2d_BSplineCurve) trimmed_bspline(const Handle(Geom2d_Curve)& curve, double first, double last) {
  Handle(Geom2d_BSplineCurve) out;
  auto bspline = Handle(Geom2d_BSplineCurve)::DownCast(curve);
  if (!bspline.IsNull() && !bspline->IsPeriodic() && bspline->FirstParameter() == first &&
      bspline->LastParameter() == last) {
    out = Handle(Geom2d_BSplineCurve)::DownCast(bspline->Copy());
  } else {
    out = Geom2dConvert::CurveToBSplineCurve(new Geom2d_TrimmedCurve(curve, first, last));
  }
  if (out->IsPeriodic()) out->SetNotPeriodic();
  return out;
}

std::vector<WireUses> face_pcurves(
    const TopoDS_Face& face, const std::function<int(const TopoDS_Edge&)>& edge_number,
    const std::function<Handle(Geom2d_BSplineCurve)(const Handle(Geom2d_Curve)&, double, double)>& to_bspline) {
  std::vector<WireUses> wires;
  int wire_number = 0;
  for (TopoDS_Iterator it(face); it.More(); it.Next()) {
    if (it.Value().ShapeType() != TopAbs_WIRE) continue;
    ++wire_number;
    const TopoDS_Wire& wire = TopoDS::Wire(it.Value());
    int edge_count = 0;
    for (TopoDS_Iterator e(wire); e.More(); e.Next()) ++edge_count;
    WireUses uses;
    for (const TopoDS_Edge& edge : wire_order(wire, face)) {
      const int number = edge_number(edge);
      Standard_Real first = 0, last = 0;
      // For a seam, the edge's orientation in the wire picks which of its two pcurves this use is.
      Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, face, first, last);
      if (pcurve.IsNull())
        throw FaceConversionError("wire " + std::to_string(wire_number) + ": edge " + std::to_string(number) +
                                  " has no pcurve on the face");
      if (!(last > first))
        throw FaceConversionError("wire " + std::to_string(wire_number) + ": edge " + std::to_string(number) +
                                  " has an empty parameter range");
      EdgeUse use;
      use.curve = to_bspline(pcurve, first, last);
      const bool against = edge.Orientation() == TopAbs_REVERSED;
      if (against) use.curve->Reverse();
      use.ref = {number, against};
      use.edge_tolerance = std::max(BRep_Tool::Tolerance(edge), Precision::Confusion());
      use.end_tolerance = use.edge_tolerance;
      const TopoDS_Vertex end = TopExp::LastVertex(edge, /*CumOri=*/true);
      if (!end.IsNull()) use.end_tolerance = std::max(use.end_tolerance, BRep_Tool::Tolerance(end));
      uses.push_back(use);
    }
    if (static_cast<int>(uses.size()) != edge_count)
      throw FaceConversionError("wire " + std::to_string(wire_number) + " is not connected: " +
                                std::to_string(uses.size()) + " of its " + std::to_string(edge_count) +
                                " edges follow each other");
    if (!uses.empty()) wires.push_back(std::move(uses));
  }
  return wires;
}

}  // namespace cadnurbs
