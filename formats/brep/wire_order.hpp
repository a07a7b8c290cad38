#pragma once
// The order in which a wire's edges follow each other on a face. Internal to formats/brep: includes OCCT.
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <vector>

namespace cadnurbs {

// Takes a wire of `face` (any orientation). Returns all its edges, oriented as the wire uses them, in an
// order where each starts at the vertex where the one before ends (TopExp::Vertices, cumulated
// orientation), starting with the wire's first edge. Where several unused edges start at that vertex
// (seams, closed edges, poles) the one whose pcurve starts nearest, in (u, v), to where the last one
// ended is taken; a tie goes to the one stored first after the last. Edges without pcurves on the face
// count as far away.
// Unlike BRepTools_WireExplorer, nothing is refused for a 2D gap: the explorer accepts twice the vertex
// tolerance over OCCT's estimate of the surface's speed, which is the fastest speed on a torus (R + r) and
// a guess on a B-spline. It stopped on 67 faces of kicad-packages3d's Inductor_THT whose pcurves miss by
// a few 1e-6 where the surface is slow: a torus's inner equator (9.6e-6 rad, 6.4e-6 allowed), the pole
// of NurbsConvert's sphere (3.4e-6), the seam of its cylinder (3.5e-5, 1.8e-5 allowed). Whether such a
// gap closes is the caller's to check, in 3D.
// Stops when no unused edge starts at the vertex reached (the result is then shorter than the wire) and
// skips INTERNAL and EXTERNAL edges (they bound nothing), so a caller compares the count.
std::vector<TopoDS_Edge> wire_order(const TopoDS_Wire& wire, const TopoDS_Face& face);

}  // namespace cadnurbs
