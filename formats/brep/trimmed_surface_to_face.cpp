#include "formats/brep/trimmed_surface_to_face.hpp"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepLib.hxx>
#include <BRep_Builder.hxx>
#include <Precision.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>
#include <algorithm>

#include "core/geometry_error.hpp"
#include "formats/brep/nurbs_to_occt.hpp"

namespace cadnurbs {

namespace {

gp_Pnt point_at(const Handle(Geom_Surface)& surface, const Eigen::Vector2d& uv) { return surface->Value(uv.x(), uv.y()); }

// Largest 3D distance from the segment's start to points along it: zero for a pole.
double spread(const Handle(Geom2d_BSplineCurve)& curve, const Handle(Geom_Surface)& surface) {
  const gp_Pnt2d a = curve->Value(curve->FirstParameter());
  const gp_Pnt start = surface->Value(a.X(), a.Y());
  double out = 0;
  const int n = std::max(16, 4 * curve->NbPoles());
  for (int i = 1; i <= n; ++i) {
    const double t = curve->FirstParameter() + (curve->LastParameter() - curve->FirstParameter()) * i / n;
    const gp_Pnt2d p = curve->Value(t);
    out = std::max(out, start.Distance(surface->Value(p.X(), p.Y())));
  }
  return out;
}

TopoDS_Wire loop_wire(const TrimLoop& loop, const Handle(Geom_BSplineSurface)& surface, const TopoDS_Face& face,
                      const std::string& entity, double tolerance) {
  BRep_Builder builder;
  const size_t n = loop.segments.size();
  // Vertex i is where segment i starts (and segment i - 1 ends). Points that coincide in 3D share one
  // vertex: the two ends of a closed edge (a full circle) must be the same vertex for OCCT, as must the
  // corners a pole or a seam brings together.
  std::vector<TopoDS_Vertex> vertices(n);
  std::vector<gp_Pnt> points(n);
  for (size_t i = 0; i < n; ++i) {
    points[i] = point_at(surface, segment_start(loop.segments[i]));
    const gp_Pnt end = point_at(surface, segment_end(loop.segments[(i + n - 1) % n]));
    for (size_t j = 0; j < i && vertices[i].IsNull(); ++j)
      if (points[j].Distance(points[i]) <= tolerance) vertices[i] = vertices[j];
    if (vertices[i].IsNull()) builder.MakeVertex(vertices[i], points[i], std::max(tolerance, 2 * points[i].Distance(end)));
  }
  TopoDS_Wire wire;
  builder.MakeWire(wire);
  for (size_t i = 0; i < n; ++i) {
    const std::string name = entity + " segment " + std::to_string(i);
    const Handle(Geom2d_BSplineCurve) curve = to_occt_curve_2d(loop.segments[i], name);
    const TopoDS_Vertex first = vertices[i];
    const TopoDS_Vertex last = vertices[(i + 1) % n];
    TopoDS_Edge edge;
    if (spread(curve, surface) <= tolerance) {
      // A pole: OCCT wants a degenerated edge with only its pcurve.
      builder.MakeEdge(edge);
      builder.UpdateEdge(edge, curve, face, tolerance);
      builder.Range(edge, curve->FirstParameter(), curve->LastParameter());
      builder.Degenerated(edge, true);
      builder.Add(edge, first.Oriented(TopAbs_FORWARD));
      builder.Add(edge, last.Oriented(TopAbs_REVERSED));
    } else {
      BRepBuilderAPI_MakeEdge make(curve, surface, first, last, curve->FirstParameter(), curve->LastParameter());
      if (!make.IsDone())
        throw GeometryError(name, "OCCT cannot make an edge of it (BRepBuilderAPI_EdgeError " +
                                      std::to_string(static_cast<int>(make.Error())) + ")");
      edge = make.Edge();
    }
    builder.Add(wire, edge);
  }
  wire.Closed(true);
  return wire;
}

}  // namespace

TopoDS_Face trimmed_surface_to_face(const TrimmedSurface& trimmed, const std::string& entity, double tolerance) {
  validate(trimmed, entity, 1e-6 * std::max(1.0, std::abs(trimmed.surface.u_end() - trimmed.surface.u_start()) +
                                                     std::abs(trimmed.surface.v_end() - trimmed.surface.v_start())));
  const Handle(Geom_BSplineSurface) surface = to_occt_surface(trimmed.surface, entity);
  if (trimmed.loops.empty()) {
    BRepBuilderAPI_MakeFace make(surface, Precision::Confusion());
    if (!make.IsDone())
      throw GeometryError(entity, "OCCT cannot make a face of the surface (BRepBuilderAPI_FaceError " +
                                      std::to_string(static_cast<int>(make.Error())) + ")");
    return make.Face();
  }
  BRep_Builder builder;
  TopoDS_Face face;
  builder.MakeFace(face, surface, tolerance);
  for (size_t l = 0; l < trimmed.loops.size(); ++l)
    builder.Add(face, loop_wire(trimmed.loops[l], surface, face, entity + " loop " + std::to_string(l), tolerance));
  BRepLib::BuildCurves3d(face, tolerance);
  return face;
}

}  // namespace cadnurbs
