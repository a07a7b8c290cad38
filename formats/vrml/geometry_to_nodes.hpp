#pragma once
// One piece of core geometry as a VRML97 or X3D geometry node, numbers tagged with the precision they
// are to be written with (nurbs_tolerances.hpp):
//   VRML97: NurbsSurface, TrimmedSurface { surface NurbsSurface, trimmingContour [Contour2D {children
//           [NurbsCurve2D | Polyline2D]}] }, NurbsCurve, IndexedFaceSet.
//   X3D:    NurbsPatchSurface, NurbsTrimmedSurface (surface fields inline, trimmingContour as above with
//           NurbsCurve2D | ContourPolyline2D), NurbsCurve, IndexedFaceSet; controlPoint and coord as
//           Coordinate, or CoordinateDouble when the precision asked for is finer than single precision.
// Weights are written only for rational entities whose weights are not all 1. Mesh vertices are written
// within τ, unit normals within 1e-3 (shading only; 0.06°), equal normals once. A PolygonMesh is an
// IndexedFaceSet of its polygons (convex, flat-shaded: no normals, creaseAngle 0).
#include "core/scene.hpp"
#include "core/tessellation_hints.hpp"
#include "formats/vrml/node_graph.hpp"

namespace cadnurbs {

struct GeometryPrecision {
  double coordinate_tolerance = 0.0;  // τ, > 0, in the geometry's own (local) units
  int significant_digits = 0;         // > 0 overrides the tolerances
  bool homogeneous = true;            // controlPoint as w·P
};

// The geometry node of `geometry`. Expects valid geometry (core validate). `hints` (NURBS faces only, may
// be null): the tessellation counts to write, non-zero ones only.
NodePtr geometry_node(const Geometry& geometry, VrmlDialect dialect, const GeometryPrecision& precision,
                      const TessellationHints* hints = nullptr);

// The precision of a knot vector written with `tolerance` (or the digits override), escalated where
// the written values would merge distinct knots or reorder them.
NumberPrecision knot_precision(const std::vector<double>& knots, double tolerance, int significant_digits);

}  // namespace cadnurbs
