#include "formats/brep/scene_to_xcaf.hpp"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepLib.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Quantity_Color.hxx>
#include <TDataStd_Name.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <optional>

#include "core/bounding_box.hpp"
#include "core/geometry_error.hpp"
#include "core/length_unit.hpp"
#include "formats/brep/nurbs_to_occt.hpp"
#include "formats/brep/trimmed_surface_to_face.hpp"

namespace cadnurbs {

namespace {

// The scene with coordinates in millimetres.
TopLoc_Location to_location(const Eigen::Affine3d& transform, const std::string& entity) {
  if (transform.matrix().isIdentity(0.0)) return TopLoc_Location();
  const auto& m = transform.matrix();
  gp_Trsf trsf;
  try {
    trsf.SetValues(m(0, 0), m(0, 1), m(0, 2), m(0, 3), m(1, 0), m(1, 1), m(1, 2), m(1, 3), m(2, 0), m(2, 1), m(2, 2),
                   m(2, 3));
  } catch (const Standard_Failure&) {
    throw GeometryError(entity, "transform is not a rigid motion (OCCT needs rotation, translation and uniform scale)");
  }
  return TopLoc_Location(trsf);
}

Quantity_Color to_occt(const Colour& c) { return Quantity_Color(c.r, c.g, c.b, Quantity_TOC_sRGB); }

// A mesh as planar triangular faces (sewn with the other faces of its part).
std::vector<TopoDS_Face> mesh_faces(const TriangleMesh& mesh) {
  std::vector<TopoDS_Face> faces;
  for (const auto& t : mesh.triangles) {
    const auto& a = mesh.positions[t[0]];
    const auto& b = mesh.positions[t[1]];
    const auto& c = mesh.positions[t[2]];
    if ((b - a).cross(c - a).norm() == 0.0) continue;  // no plane
    BRepBuilderAPI_MakePolygon polygon(gp_Pnt(a.x(), a.y(), a.z()), gp_Pnt(b.x(), b.y(), b.z()),
                                       gp_Pnt(c.x(), c.y(), c.z()), /*Close=*/true);
    if (!polygon.IsDone()) continue;
    BRepBuilderAPI_MakeFace face(polygon.Wire(), /*OnlyPlane=*/true);
    if (face.IsDone()) faces.push_back(face.Face());
  }
  return faces;
}

class XcafWriter {
 public:
  XcafWriter(const Handle(TDocStd_Document)& document, double sewing_tolerance, bool face_names)
      : shapes_(XCAFDoc_DocumentTool::ShapeTool(document->Main())),
        colours_(XCAFDoc_DocumentTool::ColorTool(document->Main())),
        tolerance_(sewing_tolerance),
        face_names_(face_names) {}

  // The label of `node` (a part or an assembly), added as a free shape.
  TDF_Label add(const SceneNode& node, const std::string& path) {
    if (node.children.empty()) return add_part(node, path);
    TDF_Label assembly = shapes_->NewShape();
    set_name(assembly, node.name);
    if (node.colour) colours_->SetColor(assembly, to_occt(*node.colour), XCAFDoc_ColorSurf);
    if (!node.shapes.empty()) {
      SceneNode own = node;
      own.children.clear();
      own.transform = Eigen::Affine3d::Identity();
      shapes_->AddComponent(assembly, add_part(own, path), TopLoc_Location());
    }
    for (const auto& child : node.children) {
      const std::string child_path = path + "/" + display_name(child);
      const TDF_Label component = shapes_->AddComponent(assembly, add(child, child_path), to_location(child.transform, child_path));
      set_name(component, child.name);
    }
    return assembly;
  }

 private:
  TDF_Label add_part(const SceneNode& node, const std::string& path) {
    BRepBuilderAPI_Sewing sewing(tolerance_);
    std::vector<std::pair<TopoDS_Face, const Shape*>> faces;
    std::vector<TopoDS_Edge> curves;
    for (size_t i = 0; i < node.shapes.size(); ++i) {
      const Shape& shape = node.shapes[i];
      const std::string entity =
          path + "/" + (display_name(shape).empty() ? "shape " + std::to_string(i) : display_name(shape));
      if (const auto* trimmed = std::get_if<TrimmedSurface>(&shape.geometry)) {
        faces.emplace_back(trimmed_surface_to_face(*trimmed, entity, 0.1 * tolerance_), &shape);
      } else if (const auto* mesh = std::get_if<TriangleMesh>(&shape.geometry)) {
        for (const auto& f : mesh_faces(*mesh)) faces.emplace_back(f, &shape);
      } else if (const auto* polygons = std::get_if<PolygonMesh>(&shape.geometry)) {
        for (const auto& f : mesh_faces(triangulated(*polygons))) faces.emplace_back(f, &shape);
      } else {
        const auto& curve = std::get<NurbsCurve>(shape.geometry);
        BRepBuilderAPI_MakeEdge edge(to_occt_curve(curve, entity));
        if (!edge.IsDone()) throw GeometryError(entity, "OCCT cannot make an edge of the curve");
        curves.push_back(edge.Edge());
      }
    }
    for (const auto& f : faces) sewing.Add(f.first);
    TopoDS_Shape body;
    if (!faces.empty()) {
      sewing.Perform();
      body = solids_where_closed(sewing.SewedShape());
    }
    BRep_Builder builder;
    TopoDS_Shape part_shape = body;
    if (!curves.empty()) {
      TopoDS_Compound compound;
      builder.MakeCompound(compound);
      if (!body.IsNull()) builder.Add(compound, body);
      for (const auto& e : curves) builder.Add(compound, e);
      part_shape = compound;
    }
    if (part_shape.IsNull()) {
      TopoDS_Compound empty;
      builder.MakeCompound(empty);
      part_shape = empty;
    }
    const TDF_Label part = shapes_->AddShape(part_shape, /*makeAssembly=*/false);
    set_name(part, node.name);
    if (node.colour) colours_->SetColor(part, to_occt(*node.colour), XCAFDoc_ColorSurf);
    // Faces with their own colour or name: sub-shape labels on the sewn faces.
    for (const auto& [face, shape] : faces) {
      const bool named = face_names_ && !shape->name.empty();
      if (!shape->colour && !named) continue;
      const TopoDS_Shape sewn = sewing.IsModified(face) ? sewing.Modified(face) : face;
      TDF_Label sub = shapes_->AddSubShape(part, sewn);
      if (sub.IsNull()) continue;
      if (named) set_name(sub, shape->name);
      if (shape->colour) colours_->SetColor(sub, to_occt(*shape->colour), XCAFDoc_ColorSurf);
    }
    return part;
  }

  // Shells that close become solids (oriented so that the material is inside); the rest stays as sewn.
  static TopoDS_Shape solids_where_closed(const TopoDS_Shape& sewn) {
    std::vector<TopoDS_Shape> pieces;
    bool any_solid = false;
    for (TopExp_Explorer ex(sewn, TopAbs_SHELL); ex.More(); ex.Next()) {
      TopoDS_Shell shell = TopoDS::Shell(ex.Current());
      if (BRep_Tool::IsClosed(shell)) {
        BRepBuilderAPI_MakeSolid make(shell);
        if (make.IsDone()) {
          TopoDS_Solid solid = make.Solid();
          BRepLib::OrientClosedSolid(solid);
          pieces.push_back(solid);
          any_solid = true;
          continue;
        }
      }
      pieces.push_back(shell);
    }
    for (TopExp_Explorer ex(sewn, TopAbs_FACE, TopAbs_SHELL); ex.More(); ex.Next()) pieces.push_back(ex.Current());
    if (!any_solid) return sewn;
    if (pieces.size() == 1) return pieces.front();
    BRep_Builder builder;
    TopoDS_Compound compound;
    builder.MakeCompound(compound);
    for (const auto& p : pieces) builder.Add(compound, p);
    return compound;
  }

  static void set_name(const TDF_Label& label, const std::string& name) {
    if (!name.empty()) TDataStd_Name::Set(label, TCollection_ExtendedString(name.c_str(), /*isMultiByte=*/true));
  }

  Handle(XCAFDoc_ShapeTool) shapes_;
  Handle(XCAFDoc_ColorTool) colours_;
  double tolerance_;
  bool face_names_;
};

}  // namespace

Handle(TDocStd_Document) scene_to_xcaf(const Scene& input, bool face_names) {
  const Scene scene = in_unit(input, LengthUnit{});
  const auto box = scene_bounding_box(scene);
  const double diagonal = box.isEmpty() ? 0.0 : box.diagonal().norm();
  Handle(TDocStd_Document) document;
  XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", document);
  XCAFDoc_DocumentTool::SetLengthUnit(document, 1.0, UnitsMethods_LengthUnit_Millimeter);
  XcafWriter writer(document, std::max(1e-6, 1e-6 * diagonal), face_names);
  writer.add(scene.root, scene.root.name);
  XCAFDoc_DocumentTool::ShapeTool(document->Main())->UpdateAssemblies();
  return document;
}

}  // namespace cadnurbs
