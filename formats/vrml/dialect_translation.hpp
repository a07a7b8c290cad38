#pragma once
// A whole scene graph from VRML97 (with the NURBS nodes of its amendment, the blaxxun proposal) to X3D
// (its NURBS component), or back, every node kept. Only the nodes whose spelling differs change:
//   VRML97 NurbsSurface            <-> X3D NurbsPatchSurface (controlPoint: MFVec3f <-> Coordinate)
//   TrimmedSurface { surface }     <-> NurbsTrimmedSurface (the surface's fields on the trimmed node)
//   NurbsCurve2D point             <-> controlPoint;  Polyline2D point <-> ContourPolyline2D controlPoint
//   NurbsCurve controlPoint        <-> Coordinate;    NurbsTextureSurface point <-> NurbsTextureCoordinate
//   NurbsPositionInterpolator keyValue, keyWeight <-> controlPoint (Coordinate), weight
//   NurbsGroup                      -> Group (tessellationScale dropped, said);  InlineLoadControl -> Inline
//   Switch choice, LOD level, Collision collide <-> children, children, enabled
// The numbers pass unchanged (control points keep whatever convention the file has). ROUTEs that name a
// moved field follow it (a NurbsSurface's set_controlPoint becomes set_point of the new Coordinate, DEF'd
// "<surface>_controlPoint"). A node the target dialect lacks stays a PROTO instance: CoordinateDeformer in
// X3D keeps the file's EXTERNPROTO (or gets white_dune's); an X3D-only node in VRML97 (HAnim, ColorRGBA,
// IndexedTriangleSet...) gets an EXTERNPROTO of urn:web3d:x3d:node:<Name>. Declarations of the amendment's
// nodes are dropped where the target has them built in (X3D) or where the writer declares them from the
// cadnurbs PROTO library (VRML97); fields the target's node lacks (metadata in VRML97, ccw in X3D) are
// dropped, each kind said once.
#include <string>
#include <vector>

#include "formats/vrml/node_graph.hpp"

namespace cadnurbs {

// Translates `document` in place to `target` (also from VRML97 to VRML97: the amendment's nodes then
// get the cadnurbs PROTO library's declarations, fields it does not declare dropped). Returns one note per kind of change that loses something
// ("2 NurbsGroup tessellationScale dropped: X3D's Group has none"), in the order first met.
std::vector<std::string> translate_dialect(NodeDocument& document, VrmlDialect target);

}  // namespace cadnurbs
