#include "formats/brep/face_mesh.hpp"

#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <GeomLProp_SLProps.hxx>
#include <Poly_Triangulation.hxx>
#include <stdexcept>

#include "formats/brep/face_mesh_guard.hpp"

namespace cadnurbs {

TriangleMesh face_mesh(const TopoDS_Face& face, double deflection) {
  if (const std::string problem = why_not_meshable(face); !problem.empty())
    throw std::domain_error("not meshed either: " + problem);
  BRepMesh_IncrementalMesh mesher(face, deflection, /*isRelative=*/false, /*theAngDeflection=*/0.5);
  TopLoc_Location location;
  const Handle(Poly_Triangulation) triangulation = BRep_Tool::Triangulation(face, location);
  TriangleMesh mesh;
  if (triangulation.IsNull()) return mesh;
  const gp_Trsf to_model = location.Transformation();
  const bool reversed = face.Orientation() == TopAbs_REVERSED;
  for (int i = 1; i <= triangulation->NbNodes(); ++i) {
    const gp_Pnt p = triangulation->Node(i).Transformed(to_model);
    mesh.positions.emplace_back(p.X(), p.Y(), p.Z());
  }
  // Normals from the surface at the nodes' (u, v), turned with the face.
  std::vector<Eigen::Vector3d> node_normals(mesh.positions.size(), Eigen::Vector3d::Zero());
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);  // location applied
  if (triangulation->HasUVNodes() && !surface.IsNull()) {
    GeomLProp_SLProps props(surface, 1, 1e-9);
    for (int i = 1; i <= triangulation->NbNodes(); ++i) {
      const gp_Pnt2d uv = triangulation->UVNode(i);
      props.SetParameters(uv.X(), uv.Y());
      if (!props.IsNormalDefined()) continue;
      const gp_Dir n = props.Normal();
      node_normals[i - 1] = Eigen::Vector3d(n.X(), n.Y(), n.Z()) * (reversed ? -1.0 : 1.0);
    }
  }
  for (int t = 1; t <= triangulation->NbTriangles(); ++t) {
    int a, b, c;
    triangulation->Triangle(t).Get(a, b, c);
    if (reversed) std::swap(b, c);
    const std::array<int, 3> corners = {a - 1, b - 1, c - 1};
    mesh.triangles.push_back(corners);
    const Eigen::Vector3d facet = (mesh.positions[corners[1]] - mesh.positions[corners[0]])
                                      .cross(mesh.positions[corners[2]] - mesh.positions[corners[0]])
                                      .normalized();
    for (int k : corners) {
      const Eigen::Vector3d& n = node_normals[k];
      mesh.corner_normals.push_back(n.isZero() || !facet.allFinite() ? facet : n);
    }
  }
  for (auto& n : mesh.corner_normals)
    if (!n.allFinite()) n = Eigen::Vector3d::Zero();
  return mesh;
}

}  // namespace cadnurbs
