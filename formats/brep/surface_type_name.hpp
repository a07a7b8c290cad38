#pragma once
// The name of a face's surface type for reports. Internal to formats/brep: includes OCCT.
#include <TopoDS_Face.hxx>
#include <string>

namespace cadnurbs {

// OCCT's class of the face's surface without "Geom_" ("Plane", "CylindricalSurface", "BSplineSurface",
// "SurfaceOfRevolution", "OffsetSurface", ...), looking through rectangular trimming; "none" when the face
// has no surface.
std::string surface_type_name(const TopoDS_Face& face);

}  // namespace cadnurbs
