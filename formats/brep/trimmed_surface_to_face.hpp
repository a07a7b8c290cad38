#pragma once
// A core trimmed surface as an OCCT face (for the STEP and IGES writers, and for measuring our output
// with OCCT). Internal to formats/brep, step and iges: includes OCCT.
#include <TopoDS_Face.hxx>
#include <string>

#include "core/trimmed_surface.hpp"

namespace cadnurbs {

// Takes a trimmed surface, the entity name for errors, and a 3D tolerance (model units) for vertices,
// edges and the 3D curves computed from the trims. Returns a FORWARD face on the surface as a
// Geom_BSplineSurface with one wire per loop, in the loops' own directions (outer counter-clockwise, holes
// clockwise, which is OCCT's rule as well); each segment an edge with its pcurve and a 3D curve computed
// from it (BRepLib::BuildCurves3d); a segment whose 3D image is one point (a pole) a degenerated edge. An
// untrimmed surface gets its natural boundary (OCCT adds seams and degenerated edges where it closes).
// Throws GeometryError(entity, reason) for invalid geometry or when OCCT refuses an edge or the face.
TopoDS_Face trimmed_surface_to_face(const TrimmedSurface& trimmed, const std::string& entity, double tolerance);

}  // namespace cadnurbs
