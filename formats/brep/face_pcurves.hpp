#pragma once
// A face's wires as 2D B-spline pcurves in wire order, the common ground of the two ways a face's
// surface is converted (direct_face, BRepBuilderAPI_NurbsConvert). Internal to formats/brep: includes OCCT.
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <functional>
#include <vector>

#include "core/trimmed_surface.hpp"

namespace cadnurbs {

// One use of an edge in a wire.
struct EdgeUse {
  Handle(Geom2d_BSplineCurve) curve;  // on the B-spline surface, in the direction the wire runs
  TrimEdgeRef ref;
  double edge_tolerance = 0;  // 3D tolerance of the edge (how far its pcurve may be from its 3D curve)
  double end_tolerance = 0;   // 3D: the larger of the edge's and the vertex's where this use ends
};
using WireUses = std::vector<EdgeUse>;

// A face as a B-spline surface and the pcurves of its wires on it.
struct BSplineFace {
  Handle(Geom_BSplineSurface) surface;
  std::vector<WireUses> wires;
};

// A pcurve, trimmed to [first, last], as a non-periodic B-spline (Geom2dConvert: the same path).
Handle(Geom2d_BSplineCurve) trimmed_bspline(const Handle(Geom2d_Curve)& curve, double first, double last);

// Takes a FORWARD face, the number of each of its edges, and how a pcurve (with its range) becomes a
// B-spline on the target surface. Returns every wire's edge uses in order (wire_order), each
// run as the wire uses it. Throws FaceConversionError for a missing pcurve, an empty edge range, or a wire
// whose edges do not all follow each other.
std::vector<WireUses> face_pcurves(
    const TopoDS_Face& face, const std::function<int(const TopoDS_Edge&)>& edge_number,
    const std::function<Handle(Geom2d_BSplineCurve)(const Handle(Geom2d_Curve)&, double, double)>& to_bspline);

}  // namespace cadnurbs
