#pragma once
// Why BRepMesh must not be given a face: the checks face_mesh runs first, because BRepMesh's Delaunay
// (OCCT 7.6) can loop without end on degenerate geometry and offers no way to stop it. Internal to
// formats/brep: includes OCCT.
#include <TopoDS_Face.hxx>
#include <string>

namespace cadnurbs {

// Bounds past which a face is not meshed, chosen far beyond real parts (1e15 model units is 1e12 m in
// mm; a weight ratio of 1e10 leaves the lightest control points 1e-10 of a say). Measured on a
// damaged capping-post.step (huge coordinates and one pcurve weight of 1e40 or 1e50): BRepMesh had not
// finished after 100 s, in its Delaunay frontier repair; with 1e30 in the same places it took 0.3 s.
inline constexpr double max_mesh_coordinate = 1e15;
inline constexpr double max_weight_ratio = 1e10;

// Takes a face. Returns "" when it may be meshed, otherwise the reason, in words for a message: its
// bounding box reaches beyond ±max_mesh_coordinate, or its B-spline surface or a B-spline pcurve of one
// of its edges has a control point beyond that, or weights that are not positive or spread by more than
// max_weight_ratio.
std::string why_not_meshable(const TopoDS_Face& face);

}  // namespace cadnurbs
