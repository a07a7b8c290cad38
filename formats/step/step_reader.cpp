#include "formats/step/step_reader.hpp"

#include <IFSelect_ReturnStatus.hxx>
#include <Interface_CheckIterator.hxx>
#include <Interface_Static.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>
#include <StepData_StepModel.hxx>
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TDF_LabelSequence.hxx>
#include <TopExp_Explorer.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <XSControl_WorkSession.hxx>
#include <cctype>
#include <filesystem>
#include <optional>

#include "core/length_unit.hpp"
#include "formats/common/file_probe.hpp"
#include "formats/brep/occt_errors.hpp"
#include "formats/brep/occt_setup.hpp"
#include "formats/brep/reader_plumbing.hpp"
#include "formats/brep/xcaf_to_scene.hpp"
#include "formats/common/file_io.hpp"
#include "formats/step/step_precheck.hpp"

namespace cadnurbs {

namespace {

// ISO 10303-21 framing: the header keyword first, the end keyword last. Catches text files and
// truncated files with a clearer message than OCCT's parser gives.
void check_framing(const std::string& path) {
  const std::string head = file_head(path, 64);
  if (head.empty()) throw FileError(path + ": empty file");
  const std::string header = "ISO-10303-21;";
  const size_t start = head.find_first_not_of(" \t\r\n\xEF\xBB\xBF");  // whitespace, UTF-8 byte order mark
  if (start == std::string::npos || head.compare(start, header.size(), header) != 0)
    throw FileError(path + ": not a STEP file (no ISO-10303-21 header)");
  std::string tail = file_tail(path, 256);
  while (!tail.empty() && std::isspace(static_cast<unsigned char>(tail.back()))) tail.pop_back();
  const std::string end = "END-ISO-10303-21;";
  if (tail.size() < end.size() || tail.compare(tail.size() - end.size(), end.size(), end) != 0)
    throw FileError(path + ": STEP file is truncated (no END-ISO-10303-21; at its end)");
}

LengthUnit file_unit(STEPControl_Reader& reader) {
  TColStd_SequenceOfAsciiString lengths, angles, solid_angles;
  reader.FileUnits(lengths, angles, solid_angles);
  if (lengths.IsEmpty()) return LengthUnit{};
  const std::string name = lengths.First().ToCString();
  if (auto unit = length_unit_named(name)) return *unit;
  return LengthUnit{name, 1.0};
}

// Reads the file into `reader`, refusing what OCCT could not read.
void read_model(STEPControl_Reader& reader, const std::string& path, const ReadStageListener& stage) {
  tell_stage(stage, "parse");
  const IFSelect_ReturnStatus status = reader.ReadFile(path.c_str());
  if (status != IFSelect_RetDone) throw FileError(path + ": STEP read failed: " + read_status_text(status));
  const Handle(StepData_StepModel) model = reader.StepModel();
  refuse_unresolved_references(reader.WS()->ModelCheckList(), model, path, "STEP");
}


// Through XCAF (names, colours, assemblies). Empty optional when XCAF gave no shape.
std::optional<BrepTranslation> read_with_xcaf(const std::string& path, const std::string& stem, const ReadStageListener& stage) {
  Handle(XCAFApp_Application) application = XCAFApp_Application::GetApplication();
  Handle(TDocStd_Document) document;
  application->NewDocument("MDTV-XCAF", document);
  XCAFDoc_DocumentTool::SetLengthUnit(document, 1.0, UnitsMethods_LengthUnit_Millimeter);
  struct Closer {
    Handle(XCAFApp_Application) application;
    Handle(TDocStd_Document) document;
    ~Closer() { application->Close(document); }
  } closer{application, document};

  STEPCAFControl_Reader reader;
  Interface_Static::SetCVal("xstep.cascade.unit", "MM");
  reader.SetColorMode(true);
  reader.SetNameMode(true);
  reader.SetLayerMode(false);
  reader.SetPropsMode(false);
  reader.SetGDTMode(false);
  reader.SetMatMode(false);
  reader.SetViewMode(false);
  read_model(reader.ChangeReader(), path, stage);
  if (reader.NbRootsForTransfer() == 0) throw FileError(path + ": no shape in the file (no transferable roots)");
  tell_stage(stage, "transfer");
  if (!reader.Transfer(document)) return std::nullopt;
  Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(document->Main());
  TDF_LabelSequence free_labels;
  shapes->GetFreeShapes(free_labels);
  bool faces = false;
  for (int i = 1; i <= free_labels.Length(); ++i) faces = faces || has_faces(XCAFDoc_ShapeTool::GetShape(free_labels(i)));
  if (!faces) return std::nullopt;
  BrepTranslation out = xcaf_to_scene(document, stem, stage);
  out.scene.source_unit = file_unit(reader.ChangeReader());
  return out;
}

// Without XCAF: geometry only.
BrepTranslation read_plain(const std::string& path, const std::string& stem, const ReadStageListener& stage) {
  STEPControl_Reader reader;
  Interface_Static::SetCVal("xstep.cascade.unit", "MM");
  read_model(reader, path, stage);
  const TopoDS_Shape shape = transfer_roots(reader, path, stage);
  BrepTranslation out = shape_to_scene(shape, stem, stage);
  out.scene.source_unit = file_unit(reader);
  return out;
}

}  // namespace

BrepTranslation read_step(const std::string& path, const ReadStageListener& stage) {
  prepare_occt();
  check_framing(path);
  precheck_step_file(path);  // what OCCT's parser would crash or hang on
  const std::string stem = std::filesystem::path(path).stem().string();
  return read_xcaf_or_plain(
      path, "STEP", [&] { return read_with_xcaf(path, stem, stage); }, [&] { return read_plain(path, stem, stage); });
}

}  // namespace cadnurbs
