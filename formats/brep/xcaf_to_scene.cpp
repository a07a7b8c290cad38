#include "formats/brep/xcaf_to_scene.hpp"

#include <BRepBndLib.hxx>
#include <BRep_Builder.hxx>
#include <Bnd_Box.hxx>
#include <Quantity_Color.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDataStd_Name.hxx>
#include <TopoDS_Compound.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <optional>
#include <set>

#include "formats/brep/brep_scene_builder.hpp"

namespace cadnurbs {

namespace {

// Chordal deflection of fallback meshes: 0.001 x the diagonal of the shapes' bounding box.
double mesh_deflection(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::Add(shape, box, /*useTriangulation=*/false);
  if (box.IsVoid()) return 0.01;
  const double diagonal = std::sqrt(box.SquareExtent());
  return diagonal > 0 ? 1e-3 * diagonal : 0.01;
}

Eigen::Affine3d to_affine(const TopLoc_Location& location) {
  const gp_Trsf trsf = location.Transformation();
  Eigen::Affine3d out = Eigen::Affine3d::Identity();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) out.matrix()(r, c) = trsf.Value(r + 1, c + 1);
  return out;
}

class XcafTranslator {
 public:
  XcafTranslator(const Handle(TDocStd_Document)& document, double deflection, const ReadStageListener& stage)
      : shapes_(XCAFDoc_DocumentTool::ShapeTool(document->Main())),
        colours_(XCAFDoc_DocumentTool::ColorTool(document->Main())),
        builder_(deflection, stage) {}

  // `default_name`: the name to use when XCAF gives none, or only the shape's type (its automatic name).
  SceneNode node(const TDF_Label& label, const std::string& parent_path, const std::string& default_name = "") {
    SceneNode out;
    TDF_Label target = label;
    if (shapes_->IsReference(label)) {
      shapes_->GetReferredShape(label, target);
      out.transform = to_affine(XCAFDoc_ShapeTool::GetLocation(label));
    }
    out.name = name(label);
    if (out.name.empty()) out.name = name(target);
    static const std::set<std::string> type_names = {"COMPOUND", "COMPSOLID", "SOLID", "SHELL", "FACE",
                                                     "WIRE",     "EDGE",      "VERTEX", "SHAPE"};
    if (!default_name.empty() && (out.name.empty() || type_names.count(out.name))) out.name = default_name;
    if (auto c = colour(label)) out.colour = c;
    else if (auto ct = colour(target)) out.colour = ct;
    const std::string path = parent_path.empty() ? out.name : parent_path + "/" + out.name;
    if (shapes_->IsAssembly(target)) {
      TDF_LabelSequence components;
      XCAFDoc_ShapeTool::GetComponents(target, components);
      for (int i = 1; i <= components.Length(); ++i) out.children.push_back(node(components(i), path));
    } else {
      builder_.add_shape(out, path, XCAFDoc_ShapeTool::GetShape(target), sub_shape_colours(target));
    }
    return out;
  }

  BrepTranslation finish(Scene scene) { return builder_.finish(std::move(scene)); }

 private:
  static std::string name(const TDF_Label& label) {
    Handle(TDataStd_Name) attribute;
    if (!label.FindAttribute(TDataStd_Name::GetID(), attribute)) return {};
    std::string text = TCollection_AsciiString(attribute->Get()).ToCString();  // UTF-8
    // ISO 10303-21: line breaks are not part of a string, but OCCT keeps the CR of a CRLF file's name
    // broken over two lines (KiCad's toroids).
    std::erase_if(text, [](char c) { return c == '\r' || c == '\n'; });
    return text;
  }

  std::optional<Colour> colour(const TDF_Label& label) const {
    Quantity_Color c;
    if (!colours_->GetColor(label, XCAFDoc_ColorSurf, c) && !colours_->GetColor(label, XCAFDoc_ColorGen, c))
      return std::nullopt;
    // STEP and IGES store sRGB; OCCT keeps linear RGB inside.
    double r, g, b;
    c.Values(r, g, b, Quantity_TOC_sRGB);
    return Colour{r, g, b};
  }

  ShapeColours sub_shape_colours(const TDF_Label& part) const {
    ShapeColours out;
    TDF_LabelSequence subs;
    XCAFDoc_ShapeTool::GetSubShapes(part, subs);
    for (int i = 1; i <= subs.Length(); ++i)
      if (auto c = colour(subs(i))) out.Bind(XCAFDoc_ShapeTool::GetShape(subs(i)), *c);
    return out;
  }

  Handle(XCAFDoc_ShapeTool) shapes_;
  Handle(XCAFDoc_ColorTool) colours_;
  BrepSceneBuilder builder_;
};

}  // namespace

BrepTranslation xcaf_to_scene(const Handle(TDocStd_Document)& document, const std::string& root_name,
                              const ReadStageListener& stage) {
  Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(document->Main());
  TDF_LabelSequence free_labels;
  shapes->GetFreeShapes(free_labels);
  TopoDS_Compound all;
  BRep_Builder builder;
  builder.MakeCompound(all);
  for (int i = 1; i <= free_labels.Length(); ++i) builder.Add(all, XCAFDoc_ShapeTool::GetShape(free_labels(i)));

  XcafTranslator translator(document, mesh_deflection(all), stage);
  Scene scene;
  if (free_labels.Length() == 1) {
    // XCAF names unnamed shapes after their type ("COMPOUND", "SOLID", ...); the file's name says more.
    scene.root = translator.node(free_labels(1), "", root_name);
  } else {
    scene.root.name = root_name;
    for (int i = 1; i <= free_labels.Length(); ++i) scene.root.children.push_back(translator.node(free_labels(i), root_name));
  }
  return translator.finish(std::move(scene));
}

BrepTranslation shape_to_scene(const TopoDS_Shape& shape, const std::string& root_name, const ReadStageListener& stage) {
  BrepSceneBuilder builder(mesh_deflection(shape), stage);
  Scene scene;
  scene.root.name = root_name;
  builder.add_shape(scene.root, root_name, shape, ShapeColours());
  return builder.finish(std::move(scene));
}

}  // namespace cadnurbs
