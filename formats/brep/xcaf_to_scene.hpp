#pragma once
// An XCAF document (as OCCT's STEP and IGES readers fill it) or a bare shape as a Scene.
// Internal to formats/brep, step and iges: includes OCCT.
#include <TDocStd_Document.hxx>
#include <TopoDS_Shape.hxx>
#include <string>

#include "formats/brep/brep_translation.hpp"
#include "formats/brep/read_stage.hpp"

namespace cadnurbs {

// Takes a document whose shapes are in millimetres. Returns the scene (unit and source_unit mm; the
// reader sets source_unit):
// - each free shape a node (the root itself when there is only one, named `root_name` when XCAF gives it
//   no name or only its type's, else children of a root named `root_name`); each assembly component a node named after the component (else its part), with the
//   component's location as transform; parts and their solids/shells as BrepSceneBuilder::add_shape says;
// - names from TDataStd_Name; colours (surface colour, else generic) from XCAFDoc_ColorTool: a face's own,
//   else its solid's/shell's, else the component's or the part's, as node and shape colours;
// - fallback faces as meshes at 0.001 x the bounding-box diagonal of all free shapes.
// `stage` hears "face N" as each face starts.
BrepTranslation xcaf_to_scene(const Handle(TDocStd_Document)& document, const std::string& root_name,
                              const ReadStageListener& stage = {});

// The same for a shape without a document: no names or colours, one root named `root_name`.
BrepTranslation shape_to_scene(const TopoDS_Shape& shape, const std::string& root_name,
                               const ReadStageListener& stage = {});

}  // namespace cadnurbs
