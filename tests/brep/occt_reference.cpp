#include "occt_reference.hpp"

#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <IGESControl_Reader.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <algorithm>
#include <stdexcept>

#include "formats/brep/occt_setup.hpp"

namespace cadnurbs::test {

OcctReference occt_reference(const TopoDS_Shape& shape) {
  OcctReference out;
  out.shape = shape;
  TopTools_IndexedMapOfShape faces, solids, solid_faces;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  TopExp::MapShapes(shape, TopAbs_SOLID, solids);
  for (int i = 1; i <= solids.Extent(); ++i) TopExp::MapShapes(solids(i), TopAbs_FACE, solid_faces);
  out.faces = faces.Extent();
  out.solids = solids.Extent();
  out.faces_all_in_solids = solids.Extent() > 0 && solid_faces.Extent() == faces.Extent();
  GProp_GProps surface, adaptive_surface;
  BRepGProp::SurfaceProperties(shape, surface);
  BRepGProp::SurfaceProperties(shape, adaptive_surface, 1e-7);
  out.area = surface.Mass();
  out.adaptive_area = adaptive_surface.Mass();
  if (out.solids > 0) {
    GProp_GProps volume, adaptive_volume;
    BRepGProp::VolumeProperties(shape, volume, /*OnlyClosed=*/true);
    BRepGProp::VolumeProperties(shape, adaptive_volume, 1e-7, /*OnlyClosed=*/true);
    out.volume = volume.Mass();
    out.adaptive_volume = adaptive_volume.Mass();
  }
  return out;
}

OcctReference occt_reference(const std::string& path) {
  prepare_occt();
  std::string extension = path.substr(path.find_last_of('.') + 1);
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  TopoDS_Shape shape;
  if (extension == "step" || extension == "stp") {
    STEPControl_Reader reader;
    Interface_Static::SetCVal("xstep.cascade.unit", "MM");
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) throw std::runtime_error(path + ": OCCT cannot read it");
    reader.TransferRoots();
    shape = reader.OneShape();
  } else {
    IGESControl_Reader reader;
    Interface_Static::SetCVal("xstep.cascade.unit", "MM");
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) throw std::runtime_error(path + ": OCCT cannot read it");
    reader.TransferRoots();
    shape = reader.OneShape();
  }
  if (shape.IsNull()) throw std::runtime_error(path + ": OCCT transferred no shape");
  return occt_reference(shape);
}

}  // namespace cadnurbs::test
