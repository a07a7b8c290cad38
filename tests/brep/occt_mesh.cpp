#include "occt_mesh.hpp"

#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <IMeshTools_Parameters.hxx>
#include <Poly_Triangulation.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>

namespace cadnurbs::test {

void occt_mesh(const TopoDS_Shape& shape, double deflection) {
  IMeshTools_Parameters p;
  p.Deflection = deflection;
  p.Angle = 1.5;
  p.Relative = Standard_False;
  p.InParallel = Standard_False;
  BRepMesh_IncrementalMesh mesher(shape, p);
}

TriangleMesh occt_triangles(const TopoDS_Shape& shape) {
  TriangleMesh mesh;
  for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next()) {
    const TopoDS_Face& face = TopoDS::Face(ex.Current());
    TopLoc_Location loc;
    const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, loc);
    if (tri.IsNull()) continue;
    const int base = static_cast<int>(mesh.positions.size());
    for (int i = 1; i <= tri->NbNodes(); ++i) {
      const gp_Pnt p = tri->Node(i).Transformed(loc.Transformation());
      mesh.positions.emplace_back(p.X(), p.Y(), p.Z());
    }
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    for (int k = 1; k <= tri->NbTriangles(); ++k) {
      int a, b, c;
      tri->Triangle(k).Get(a, b, c);
      if (reversed) std::swap(b, c);
      mesh.triangles.push_back({base + a - 1, base + b - 1, base + c - 1});
    }
  }
  return mesh;
}

}  // namespace cadnurbs::test
