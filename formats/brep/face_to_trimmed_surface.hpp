#pragma once
// One B-rep face as a trimmed NURBS surface. Internal to formats/brep: includes OCCT.
#include <TopoDS_Face.hxx>
#include <stdexcept>

#include "core/trimmed_surface.hpp"
#include "formats/brep/edge_numbering.hpp"

namespace cadnurbs {

// Why a face could not be converted; what() is the reason, one line.
class FaceConversionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Takes `face` oriented as its shell uses it, and the scene's edge numbering. Returns:
// - the surface as a non-periodic NURBS (BRepBuilderAPI_NurbsConvert: exact for planes, cylinders, cones,
//   spheres, tori, revolutions, extrusions; B-splines kept; offsets approximated by OCCT); periodic
//   B-splines unperiodized, with the pcurves shifted by whole periods, or the surface re-based, when the
//   face crosses the seam of the parameterization;
// - one loop per wire: the edges' pcurves on the converted surface in wire order (wire_order),
//   each trimmed to its edge and run as the wire uses it, with TrimEdgeRef{edges.number(edge), runs
//   against the edge's own direction}; a seam gives two segments with one edge number, a degenerated edge
//   a segment along its pole; a pcurve a whole period away from its neighbours on a closed surface moved
//   next to them (align_pcurves);
// - for a REVERSED face, the surface mirrored in u (u -> a + b - u) so that Su x Sv points out of the
//   material;
// - loops outer counter-clockwise, holes clockwise (orient_loops); gaps between segments closed when the
//   3D gap is within the vertex tolerance (a straight bridge where the whole gap maps to one 3D point, as at
//   a pole without a degenerated edge); the result passes core's validate with its default tolerance.
// Throws FaceConversionError, GeometryError or Standard_Failure when the face cannot be converted.
TrimmedSurface face_to_trimmed_surface(const TopoDS_Face& face, EdgeNumbering& edges);

}  // namespace cadnurbs
