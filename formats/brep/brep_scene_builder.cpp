#include "formats/brep/brep_scene_builder.hpp"

#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <algorithm>

#include "core/repair_trimming_loops.hpp"
#include "formats/brep/face_mesh.hpp"
#include "formats/brep/face_to_trimmed_surface.hpp"
#include "formats/brep/occt_errors.hpp"
#include "formats/brep/rebuild_stray_pcurves.hpp"
#include "formats/brep/surface_type_name.hpp"

namespace cadnurbs {

namespace {

std::vector<TopoDS_Face> faces_of(const TopoDS_Shape& container) {
  TopTools_IndexedMapOfShape map;
  TopExp::MapShapes(container, TopAbs_FACE, map);
  std::vector<TopoDS_Face> faces;
  for (int i = 1; i <= map.Extent(); ++i) faces.push_back(TopoDS::Face(map(i)));
  return faces;
}

}  // namespace

const BrepSceneBuilder::Converted& BrepSceneBuilder::convert(const TopoDS_Face& face) {
  if (const size_t* index = converted_index_.Seek(face)) return converted_[*index];
  Converted result;
  result.surface_type = surface_type_name(face);
  try {
    OCC_CATCH_SIGNALS
    result.repairs = rebuild_stray_pcurves(face, stray_pcurve_limit(),
                                           [this](const TopoDS_Edge& edge) { return edges_.number(edge); });
    TrimmedSurface trimmed = face_to_trimmed_surface(face, edges_);
    // The one check of loops every output sees (core/repair_trimming_loops): what it refuses is meshed.
    for (auto& line : repair_trimming_loops(trimmed, "face")) result.repairs.push_back(std::move(line));
    result.geometry = std::move(trimmed);
  } catch (const Standard_Failure& failure) {
    result.fallback_reason = occt_failure_text(failure);
  } catch (const std::exception& error) {
    result.fallback_reason = one_line(error.what());
  }
  if (!result.fallback_reason.empty()) {
    TriangleMesh mesh;
    std::string meshing_problem;
    try {
      OCC_CATCH_SIGNALS
      mesh = face_mesh(face, deflection_);
      if (mesh.triangles.empty()) meshing_problem = "meshing gave no triangles";
    } catch (const Standard_Failure& failure) {
      meshing_problem = "meshing failed too: " + occt_failure_text(failure);
    } catch (const std::domain_error& refused) {
      meshing_problem = refused.what();
    }
    if (!meshing_problem.empty()) result.fallback_reason += "; " + meshing_problem;
    result.geometry = std::move(mesh);
  }
  converted_index_.Bind(face, converted_.size());
  converted_.push_back(std::move(result));
  return converted_.back();
}

void BrepSceneBuilder::add_faces(SceneNode& node, const std::string& node_path, const std::vector<TopoDS_Face>& faces,
                                 const ShapeColours& colours) {
  for (size_t i = 0; i < faces.size(); ++i) {
    tell_stage(stage_, "face " + std::to_string(face_count_ + 1));
    const Converted& converted = convert(faces[i]);
    const int number = static_cast<int>(i) + 1;
    Shape shape;
    shape.source_entity = "face " + std::to_string(number);
    for (const auto& what : converted.repairs)
      repairs_.push_back(node_path + " face " + std::to_string(number) + " (" + converted.surface_type + "): " + what);
    if (!converted.fallback_reason.empty()) {
      shape.source_entity += " (mesh)";
      fallbacks_.push_back({node_path, number, converted.surface_type, converted.fallback_reason});
    }
    shape.geometry = converted.geometry;
    shape.source_type = converted.surface_type;
    if (const Colour* colour = colours.Seek(faces[i])) shape.colour = *colour;
    node.shapes.push_back(std::move(shape));
    ++face_count_;
  }
}

void BrepSceneBuilder::add_shape(SceneNode& node, const std::string& node_path, const TopoDS_Shape& shape,
                                 const ShapeColours& colours) {
  if (shape.IsNull()) return;
  // Solids, then shells outside solids, then faces outside shells, each once.
  std::vector<TopoDS_Shape> containers;
  TopTools_IndexedMapOfShape solids, shells, faces;
  for (TopExp_Explorer ex(shape, TopAbs_SOLID); ex.More(); ex.Next()) solids.Add(ex.Current());
  for (TopExp_Explorer ex(shape, TopAbs_SHELL, TopAbs_SOLID); ex.More(); ex.Next()) shells.Add(ex.Current());
  for (TopExp_Explorer ex(shape, TopAbs_FACE, TopAbs_SHELL); ex.More(); ex.Next()) faces.Add(ex.Current());
  std::vector<TopoDS_Face> free_faces;
  for (int i = 1; i <= faces.Extent(); ++i) free_faces.push_back(TopoDS::Face(faces(i)));

  if (solids.Extent() + shells.Extent() == 1 && free_faces.empty()) {
    const TopoDS_Shape& only = solids.Extent() == 1 ? solids(1) : shells(1);
    if (const Colour* colour = colours.Seek(only)) node.colour = *colour;
    add_faces(node, node_path, faces_of(only), colours);
    return;
  }
  auto add_child = [&](const TopoDS_Shape& container, const std::string& name) {
    SceneNode child;
    child.source_entity = name;
    if (const Colour* colour = colours.Seek(container)) child.colour = *colour;
    add_faces(child, node_path + "/" + name, faces_of(container), colours);
    node.children.push_back(std::move(child));
  };
  for (int i = 1; i <= solids.Extent(); ++i) add_child(solids(i), "solid " + std::to_string(i));
  for (int i = 1; i <= shells.Extent(); ++i) add_child(shells(i), "shell " + std::to_string(i));
  add_faces(node, node_path, free_faces, colours);
}

BrepTranslation BrepSceneBuilder::finish(Scene scene) {
  BrepTranslation out;
  out.scene = std::move(scene);
  out.fallbacks = std::move(fallbacks_);
  out.repairs = std::move(repairs_);
  out.face_count = face_count_;
  out.degenerated_edges = edges_.degenerated();
  return out;
}

}  // namespace cadnurbs
