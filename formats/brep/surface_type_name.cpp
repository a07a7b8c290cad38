#include "formats/brep/surface_type_name.hpp"

#include <BRep_Tool.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_Surface.hxx>

namespace cadnurbs {

std::string surface_type_name(const TopoDS_Face& face) {
  TopLoc_Location location;
  Handle(Geom_Surface) surface = BRep_Tool::Surface(face, location);
  if (surface.IsNull()) return "none";
  while (auto trimmed = Handle(Geom_RectangularTrimmedSurface)::DownCast(surface)) surface = trimmed->BasisSurface();
  std::string name = surface->DynamicType()->Name();
  if (name.rfind("Geom_", 0) == 0) name.erase(0, 5);
  return name;
}

}  // namespace cadnurbs
