#pragma once
// The fast, exact conversion of the common faces. Internal to formats/brep: includes OCCT.
#include <TopoDS_Face.hxx>
#include <optional>

#include "formats/brep/edge_numbering.hpp"
#include "formats/brep/face_pcurves.hpp"

namespace cadnurbs {

// Takes a face (any orientation) and the scene's edge numbering. Returns the face's surface as a B-spline
// with the face's pcurves on it, exactly:
// - a B-spline or Bezier surface as it is, its pcurves converted (Geom2dConvert keeps their paths);
// - a plane, cylinder, cone, sphere, torus, surface of revolution or of linear extrusion converted over the
//   face's (u, v) bounds, at most one period even after rounding (GeomConvert; a torus straight through
//   Convert_TorusToBSplineSurface, which takes any radii). Where the conversion keeps a parameter (a plane's two, a cylinder's
//   or cone's axial one) pcurves pass unchanged; where it changes one (angles become rational quadratic
//   parameters) iso-parameter lines (Geom2d_Line, or B-splines whose poles lie on one iso-line) are mapped
//   by their end points, which is exact because the map is monotone in each parameter.
// Returns nullopt for other surfaces (offsets, ...) and for pcurves that run across a changed parameter:
// those need BRepBuilderAPI_NurbsConvert, which projects the edges' 3D curves (and costs far more).
std::optional<BSplineFace> direct_face(const TopoDS_Face& face, EdgeNumbering& edges);

}  // namespace cadnurbs
