#pragma once
// A planar face bounded by straight edges as exact polygons. A plane is what most faces of mechanical
// and electronic parts are, and as a trimmed NURBS it costs a bilinear patch plus one trimming curve per
// edge; its polygon is the same surface, exactly, at a fraction of the bytes.
#include <optional>

#include "core/polygon_mesh.hpp"
#include "core/trimmed_surface.hpp"

namespace cadnurbs {

// When `face`'s surface is an affine map of (u,v) (order 2 x 2, 2 x 2 control points forming a
// parallelogram within `tolerance`, equal weights) and every trimming segment is straight in (u,v)
// within the parameter tolerance that keeps 3D points within `tolerance` (straight_segment_points):
// the trimmed region in 3D as convex polygons, counter-clockwise about Su x Sv. One loop that is convex
// is one polygon (collinear vertices kept: they are where neighbouring faces meet it); anything else is
// triangulated (CGAL constrained Delaunay, holes by the even-odd rule) and the triangles merged into
// convex polygons (merge_convex_polygons). An untrimmed face is its parallelogram.
// A planar bilinear patch that is no parallelogram (a trapezoid: exporters make them) maps only its
// iso-lines to straight lines: it qualifies when it has one convex loop running along iso-lines (or
// none), which is then its one polygon. Nothing when the face is not such a face, or a loop bounds no
// area.
std::optional<PolygonMesh> planar_face_polygons(const TrimmedSurface& face, double tolerance);

}  // namespace cadnurbs
