// occt_mesh_to_stl: a STEP or IGES part meshed by OpenCASCADE's BRepMesh_IncrementalMesh (not by our
// tessellator) and written as binary STL: "a CAD part tessellated finely by another kernel", the kind
// of input issue 38 item 6 holds the Loop fit's maximum against (bench/subdivision_fit_table.py
// --held-out builds it, with nothing kept in the repository).
//
// usage: occt_mesh_to_stl IN.step|IN.iges OUT.stl RELATIVE_DEFLECTION
//   the deflection is a share of the part's bounding-box diagonal (absolute deflection = share x diagonal,
//   angular deflection 0.3 rad, so curved faces get fine fans as a CAD exporter's "fine" setting does).
// Not in CMake (bench/CMakeLists.txt builds the tessellation benchmarks only with CADNURBS_BENCH):
//   g++ -O2 -std=c++20 -I/usr/include/opencascade bench/occt_mesh_to_stl.cpp -o occt_mesh_to_stl \
//     -lTKSTEP -lTKSTEPBase -lTKSTEPAttr -lTKSTEP209 -lTKIGES -lTKXSBase -lTKMesh -lTKSTL -lTKTopAlgo \
//     -lTKGeomAlgo -lTKBRep -lTKGeomBase -lTKG3d -lTKG2d -lTKMath -lTKernel
// Exit status 1 with one line on stderr when the file does not read or meshes to nothing.
#include <BRepBndLib.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <Bnd_Box.hxx>
#include <IGESControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <StlAPI_Writer.hxx>
#include <TopoDS_Shape.hxx>
#include <cmath>
#include <cstdio>
#include <string>

namespace {

TopoDS_Shape read_part(const std::string& path) {
  const std::string lower = [&] {
    std::string s = path;
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
  }();
  const bool iges = lower.ends_with(".igs") || lower.ends_with(".iges");
  XSControl_Reader* reader = iges ? static_cast<XSControl_Reader*>(new IGESControl_Reader)
                                  : static_cast<XSControl_Reader*>(new STEPControl_Reader);
  TopoDS_Shape shape;
  if (reader->ReadFile(path.c_str()) == IFSelect_RetDone) {
    reader->TransferRoots();
    shape = reader->OneShape();
  }
  delete reader;
  return shape;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: occt_mesh_to_stl IN.step|IN.iges OUT.stl RELATIVE_DEFLECTION\n");
    return 2;
  }
  const TopoDS_Shape shape = read_part(argv[1]);
  if (shape.IsNull()) {
    std::fprintf(stderr, "%s: OpenCASCADE read no shape\n", argv[1]);
    return 1;
  }
  Bnd_Box box;
  BRepBndLib::Add(shape, box);
  const double diagonal = std::sqrt(box.SquareExtent());
  BRepMesh_IncrementalMesh mesher(shape, std::stod(argv[3]) * diagonal, Standard_False, 0.3, Standard_False);
  StlAPI_Writer writer;
  writer.ASCIIMode() = Standard_False;
  if (!writer.Write(shape, argv[2])) {
    std::fprintf(stderr, "%s: no triangles to write\n", argv[2]);
    return 1;
  }
  return 0;
}
