#pragma once
// Gathers B-rep shapes into scene nodes: solids and shells as nodes, faces as trimmed NURBS shapes (or
// meshes when they cannot be converted), one edge numbering for the whole scene.
// Internal to formats/brep: includes OCCT.
#include <NCollection_DataMap.hxx>
#include <TopTools_OrientedShapeMapHasher.hxx>
#include <TopTools_ShapeMapHasher.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <string>
#include <utility>
#include <vector>

#include "formats/brep/brep_translation.hpp"
#include "formats/brep/edge_numbering.hpp"
#include "formats/brep/read_stage.hpp"

namespace cadnurbs {

// Colours given to sub-shapes (faces, solids, shells) of the shape being added; orientation ignored.
using ShapeColours = NCollection_DataMap<TopoDS_Shape, Colour, TopTools_ShapeMapHasher>;

class BrepSceneBuilder {
 public:
  // `mesh_deflection`: chordal deflection, in model units, of the meshes written for faces that fail.
  // `stage` hears "face N" as face N starts.
  BrepSceneBuilder(double mesh_deflection, ReadStageListener stage)
      : deflection_(mesh_deflection), stage_(std::move(stage)) {}

  // Adds the content of `shape` to `node` (`node_path`: its name path, for reports):
  // - a shape holding exactly one solid or shell and no other face: its faces become the node's shapes;
  // - otherwise each solid ("solid K") and each shell outside the solids ("shell K") becomes a child node
  //   (those are its source_entity: generated, not names from the file);
  // - faces outside any shell become the node's shapes.
  // Face shapes have no name (STEP/IGES faces rarely carry one) and the source_entity "face N" (N: index in
  // the solid's/shell's TopExp::MapShapes order) or, when written as a mesh, "face N (mesh)"; colours from
  // `colours` (face, else solid/shell node colour).
  // A face used again (another instance of a part) reuses its first conversion.
  void add_shape(SceneNode& node, const std::string& node_path, const TopoDS_Shape& shape,
                 const ShapeColours& colours);

  // The result: `scene` plus the fallbacks, the face count and the degenerated-edge flags gathered.
  BrepTranslation finish(Scene scene);

 private:
  struct Converted {
    Geometry geometry;
    std::string surface_type;
    std::string fallback_reason;  // empty: a trimmed NURBS
    std::vector<std::string> repairs;  // pcurves rebuilt (rebuild_stray_pcurves), then what
                                       // repair_trimming_loops did to its loops
  };
  const Converted& convert(const TopoDS_Face& face);
  // A pcurve further than this from its edge is rebuilt from the edge's 3D curve (rebuild_stray_pcurves):
  // a tenth of the default deviation, which the mesh deflection is (1e-3 of the bounding-box diagonal).
  double stray_pcurve_limit() const { return 0.1 * deflection_; }
  void add_faces(SceneNode& node, const std::string& node_path, const std::vector<TopoDS_Face>& faces,
                 const ShapeColours& colours);

  double deflection_;
  ReadStageListener stage_;
  EdgeNumbering edges_;
  std::vector<FaceFallback> fallbacks_;
  std::vector<std::string> repairs_;
  int face_count_ = 0;
  std::vector<Converted> converted_;
  NCollection_DataMap<TopoDS_Shape, size_t, TopTools_OrientedShapeMapHasher> converted_index_;
};

}  // namespace cadnurbs
