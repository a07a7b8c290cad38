#include "formats/brep/wire_order.hpp"

#include <BRep_Tool.hxx>
#include <Precision.hxx>
#include <TopExp.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Vertex.hxx>
#include <gp_Pnt2d.hxx>
#include <optional>

namespace cadnurbs {

namespace {

struct Use {
  TopoDS_Edge edge;
  TopoDS_Vertex first, last;
  std::optional<gp_Pnt2d> start, end;  // of the pcurve, in the direction the wire runs
  bool taken = false;
};

Use make_use(const TopoDS_Edge& edge, const TopoDS_Face& face) {
  Use use;
  use.edge = edge;
  TopExp::Vertices(edge, use.first, use.last, /*CumOri=*/true);
  Standard_Real first = 0, last = 0;
  const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, face, first, last);
  if (!pcurve.IsNull() && !Precision::IsInfinite(first) && !Precision::IsInfinite(last)) {
    use.start = pcurve->Value(first);
    use.end = pcurve->Value(last);
    if (edge.Orientation() == TopAbs_REVERSED) std::swap(use.start, use.end);
  }
  return use;
}

// Whether `use` may follow an edge ending at `vertex`: the same vertex, or both ends without one.
bool starts_at(const Use& use, const TopoDS_Vertex& vertex) {
  if (use.first.IsNull() || vertex.IsNull()) return use.first.IsNull() && vertex.IsNull();
  return use.first.IsSame(vertex);
}

}  // namespace

std::vector<TopoDS_Edge> wire_order(const TopoDS_Wire& wire, const TopoDS_Face& face) {
  std::vector<Use> uses;
  for (TopoDS_Iterator it(wire); it.More(); it.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(it.Value());
    if (edge.Orientation() == TopAbs_FORWARD || edge.Orientation() == TopAbs_REVERSED)
      uses.push_back(make_use(edge, face));
  }
  std::vector<TopoDS_Edge> out;
  if (uses.empty()) return out;
  const size_t n = uses.size();
  size_t current = 0;
  uses[0].taken = true;
  out.push_back(uses[0].edge);
  while (out.size() < n) {
    const Use& last = uses[current];
    std::optional<size_t> best;
    double best_distance = Precision::Infinite();
    // Scanning from the edge stored after the last one makes the first of equally near edges that one.
    for (size_t k = 1; k < n; ++k) {
      const size_t i = (current + k) % n;
      const Use& candidate = uses[i];
      if (candidate.taken || !starts_at(candidate, last.last)) continue;
      const double distance =
          last.end && candidate.start ? last.end->Distance(*candidate.start) : Precision::Infinite();
      if (!best || distance < best_distance) best = i, best_distance = distance;
    }
    if (!best) break;
    current = *best;
    uses[current].taken = true;
    out.push_back(uses[current].edge);
  }
  return out;
}

}  // namespace cadnurbs
