#pragma once
// OCCT's own figures for a STEP or IGES file, read by OCCT's plain readers (no cadnurbs code), as the
// reference the translation is measured against.
#include <TopoDS_Shape.hxx>
#include <string>

namespace cadnurbs::test {

struct OcctReference {
  TopoDS_Shape shape;  // all roots, in millimetres
  int faces = 0;       // TopExp::MapShapes(shape, FACE): every instance of a face counted
  int solids = 0;
  bool faces_all_in_solids = false;
  // BRepGProp's default integration (fixed Gauss points per span), and its adaptive one (precision 1e-7).
  // Neither is exact: the default is off by up to 0.3 % on periodic rational B-spline faces (dm1-id-214),
  // the adaptive one by as much on a linear extrusion (side.iges).
  double area = 0, adaptive_area = 0;
  double volume = 0, adaptive_volume = 0;  // of the solids
};

// Reads `path` (.step/.stp or .iges/.igs by extension) with STEPControl_Reader or IGESControl_Reader.
// Throws std::runtime_error when OCCT cannot.
OcctReference occt_reference(const std::string& path);

// The same figures for a shape already in memory.
OcctReference occt_reference(const TopoDS_Shape& shape);

}  // namespace cadnurbs::test
