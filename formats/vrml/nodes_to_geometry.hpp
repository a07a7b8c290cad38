#pragma once
// Geometry nodes back to core geometry, validated:
//   NurbsSurface / NurbsPatchSurface -> untrimmed TrimmedSurface; TrimmedSurface / NurbsTrimmedSurface ->
//   TrimmedSurface with one loop per Contour2D (NurbsCurve2D, Polyline2D / ContourPolyline2D segments);
//   NurbsCurve -> 3D NurbsCurve; IndexedFaceSet -> TriangleMesh (polygons fanned, ccw FALSE flipped,
//   normals per corner from normalIndex, coordIndex or per face); and, for files of other tools,
//   IndexedLineSet -> one order-2 NurbsCurve per polyline (exact), Box and IndexedTriangleSet ->
//   TriangleMesh (exact), Sphere -> the exact rational biquadratic NURBS (poles on the y axis).
// Control points are read as w·P (homogeneous) or P. The formats' defaults apply to absent fields: order
// 3, weights 1, and an empty knot vector means a clamped uniform one on [0, 1]. A knot vector of the
// wrong length is refused, not replaced. Trimming loops must close within 1/1000 of the parameter
// domain's diagonal (files round their numbers); joints of clamped segments are then snapped shut.
// An indexed set without a coord node draws nothing (no geometry).
// Trimming segments without points and contours without segments trim nothing and are skipped.
// Fields that only steer rendering (tessellation, solid, closed, creaseAngle...) are ignored.
#include <string>
#include <vector>

#include "core/scene.hpp"
#include "formats/vrml/node_graph.hpp"

namespace cadnurbs {

struct GeometryReadContext {
  std::string file;  // for error messages
  bool homogeneous = true;
};

// Whether geometry_from_node reads nodes of `type` (others, such as Text, Cylinder or a PROTO's geometry,
// have no form here).
bool reads_geometry_node(const std::string& type);

// The geometry of a Shape's geometry node (several for an IndexedLineSet, none for an empty one).
// Throws FileError "<file>: line N: <node type>: <reason>" for geometry outside the subset or invalid.
std::vector<Geometry> geometry_from_node(const Node& node, const GeometryReadContext& context);

}  // namespace cadnurbs
