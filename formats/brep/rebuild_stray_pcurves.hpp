#pragma once
// Pcurves that do not lie on their edge, rebuilt from the edge's 3D curve. A face's trim is its pcurves;
// the face's neighbour trims along the same edge with its own. Where one pcurve's image on the surface
// strays from the edge's 3D curve, the two faces leave a gap (or overlap) that no mesh sharing the edge
// can close, and a trimmed NURBS written from it has the same crack. Projecting the 3D curve onto the
// surface again (ShapeFix_Edge, OCCT's shape healing) puts the trim back on the edge.
// Internal to formats/brep: includes OCCT.
#include <TopoDS_Face.hxx>
#include <functional>
#include <string>
#include <vector>

#include <TopoDS_Edge.hxx>

namespace cadnurbs {

// How far an edge's pcurve on `face`, mapped by the surface, lies from the edge's 3D curve: the largest
// distance from 33 points of the pcurve's image, evenly spaced in its parameter, to the nearest point
// of the 3D curve (a pcurve parameterised differently from its curve does not stray). 0 for a
// degenerated edge or one without a 3D curve.
double pcurve_stray_distance(const TopoDS_Edge& edge, const TopoDS_Face& face);

// Takes a face (its edges are changed in place: the new pcurve replaces the old one on this face only)
// and a distance `limit` > 0 in model units. Every edge of the face except seams and degenerated edges
// whose pcurve strays more than max(limit, the edge's tolerance) while its 3D curve lies on the surface
// within `limit` is given a pcurve projected from its 3D curve, kept only if it strays less than
// before and no more than `limit`. (A 3D curve off the surface is a model gap: no pcurve can follow
// it, and sewing and the tessellator's shared edges bridge it.) Returns one line per
// edge rebuilt, "pcurve of edge N was X from its 3D curve: rebuilt from it (now Y)", N from
// `edge_number`; an edge whose projection fails or is no better keeps its pcurve and gets the line
// "pcurve of edge N is X from its 3D curve: left (no better projection)".
std::vector<std::string> rebuild_stray_pcurves(const TopoDS_Face& face, double limit,
                                               const std::function<int(const TopoDS_Edge&)>& edge_number);

}  // namespace cadnurbs
