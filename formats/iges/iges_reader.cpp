#include "formats/iges/iges_reader.hpp"

#include <IGESCAFControl_Reader.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESData_GlobalSection.hxx>
#include <IGESData_IGESModel.hxx>
#include <Interface_Static.hxx>
#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>
#include <TDF_LabelSequence.hxx>
#include <TopExp_Explorer.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <XSControl_WorkSession.hxx>
#include <array>
#include <cstdlib>
#include <fstream>
#include <map>
#include <filesystem>
#include <optional>

#include "formats/common/file_probe.hpp"
#include "core/length_unit.hpp"
#include "formats/brep/occt_errors.hpp"
#include "formats/brep/occt_setup.hpp"
#include "formats/brep/reader_plumbing.hpp"
#include "formats/brep/xcaf_to_scene.hpp"
#include "formats/common/file_io.hpp"
#include "formats/iges/iges_precheck.hpp"

namespace cadnurbs {

namespace {

// The section letter in column 73 of a fixed-format IGES line.
char section_letter(const std::string& line) { return line.size() >= 73 ? line[72] : '\0'; }

// IGES framing: an 80-column Start (or Flag) line first, the Terminate line last, and as many lines of each
// section as the Terminate line counts. Catches text files, truncated files and files missing lines with a
// clearer message than OCCT's parser gives (OCCT reads what is left).
void check_framing(const std::string& path) {
  const std::string head = file_head(path, 82);
  if (head.empty()) throw FileError(path + ": empty file");
  const std::string first_line = head.substr(0, head.find_first_of("\r\n"));
  const char first = section_letter(first_line);
  if (first != 'S' && first != 'F' && first != 'C')
    throw FileError(path + ": not an IGES file (the first line is not an 80-column Start section line)");
  std::string tail = file_tail(path, 256);
  while (!tail.empty() && (tail.back() == '\n' || tail.back() == '\r' || tail.back() == ' ' || tail.back() == '\0'))
    tail.pop_back();
  const size_t line_start = tail.find_last_of("\r\n");
  const std::string last_line = line_start == std::string::npos ? tail : tail.substr(line_start + 1);
  if (section_letter(last_line) != 'T')
    throw FileError(path + ": IGES file is truncated (no Terminate section at its end)");
  if (first == 'C') return;  // compressed form: the counts mean something else

  std::map<char, long> counted;
  {
    std::ifstream in(path, std::ios::binary);
    std::string line;
    while (std::getline(in, line)) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      ++counted[section_letter(line)];
    }
  }
  static const std::array<std::pair<char, const char*>, 4> sections = {
      {{'S', "Start"}, {'G', "Global"}, {'D', "Directory Entry"}, {'P', "Parameter Data"}}};
  for (size_t k = 0; k < sections.size(); ++k) {
    const std::string field = last_line.substr(8 * k, 8);
    if (field.size() < 8 || field[0] != sections[k].first) continue;
    char* end = nullptr;
    const long expected = std::strtol(field.c_str() + 1, &end, 10);
    if (counted[sections[k].first] != expected)
      throw FileError(path + ": IGES file is damaged: its Terminate section counts " + std::to_string(expected) + " " +
                      sections[k].second + " lines, the file has " + std::to_string(counted[sections[k].first]));
  }
}

LengthUnit file_unit(const IGESControl_Reader& reader) {
  const Handle(IGESData_IGESModel) model = reader.IGESModel();
  if (model.IsNull()) return LengthUnit{};
  const IGESData_GlobalSection& global = model->GlobalSection();
  if (!global.UnitName().IsNull())
    if (auto unit = length_unit_named(global.UnitName()->ToCString())) return *unit;
  // The unit flag (IGES 5.3, global parameter 14).
  static const std::array<const char*, 12> flags = {"", "inch", "mm", "", "ft", "mi", "m", "km", "mil", "um", "cm", "uin"};
  const int flag = global.UnitFlag();
  if (flag >= 1 && flag < static_cast<int>(flags.size()) && *flags[flag])
    if (auto unit = length_unit_named(flags[flag])) return *unit;
  return LengthUnit{};
}

void read_model(IGESControl_Reader& reader, const std::string& path, const ReadStageListener& stage) {
  tell_stage(stage, "parse");
  const IFSelect_ReturnStatus status = reader.ReadFile(path.c_str());
  if (status != IFSelect_RetDone) throw FileError(path + ": IGES read failed: " + read_status_text(status));
  refuse_unresolved_references(reader.WS()->ModelCheckList(), reader.IGESModel(), path, "IGES");
}


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

  IGESCAFControl_Reader reader;
  Interface_Static::SetCVal("xstep.cascade.unit", "MM");
  reader.SetColorMode(true);
  reader.SetNameMode(true);
  reader.SetLayerMode(false);
  read_model(reader, path, stage);
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
  out.scene.source_unit = file_unit(reader);
  return out;
}

BrepTranslation read_plain(const std::string& path, const std::string& stem, const ReadStageListener& stage) {
  IGESControl_Reader reader;
  Interface_Static::SetCVal("xstep.cascade.unit", "MM");
  read_model(reader, path, stage);
  const TopoDS_Shape shape = transfer_roots(reader, path, stage);
  BrepTranslation out = shape_to_scene(shape, stem, stage);
  out.scene.source_unit = file_unit(reader);
  return out;
}

}  // namespace

BrepTranslation read_iges(const std::string& path, const ReadStageListener& stage) {
  prepare_occt();
  check_framing(path);
  precheck_iges_file(path);  // what OCCT's reader would misread or allocate for blindly
  const std::string stem = std::filesystem::path(path).stem().string();
  return read_xcaf_or_plain(
      path, "IGES", [&] { return read_with_xcaf(path, stem, stage); }, [&] { return read_plain(path, stem, stage); });
}

}  // namespace cadnurbs
