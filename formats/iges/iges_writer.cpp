#include "formats/iges/iges_writer.hpp"

#include <IGESCAFControl_Writer.hxx>
#include <IGESData_GlobalSection.hxx>
#include <IGESData_IGESModel.hxx>
#include <Interface_Static.hxx>
#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>
#include <TCollection_HAsciiString.hxx>
#include <XCAFApp_Application.hxx>
#include <filesystem>
#include <sstream>

#include "core/geometry_error.hpp"
#include "formats/brep/occt_errors.hpp"
#include "formats/brep/occt_setup.hpp"
#include "formats/brep/output_time_stamp.hpp"
#include "formats/brep/scene_to_xcaf.hpp"
#include "formats/common/file_io.hpp"

namespace cadnurbs {

namespace {

Handle(TCollection_HAsciiString) text(const std::string& s) { return new TCollection_HAsciiString(s.c_str()); }

// IGES dates are "YYYYMMDD.HHNNSS".
std::string iges_date(const std::string& iso) {
  return iso.substr(0, 4) + iso.substr(5, 2) + iso.substr(8, 2) + "." + iso.substr(11, 2) + iso.substr(14, 2) +
         iso.substr(17, 2);
}

}  // namespace

void write_iges(const std::string& path, const Scene& scene) {
  prepare_occt();
  std::string bytes;
  try {
    validate(scene);
    OCC_CATCH_SIGNALS
    // Without face names: OCCT's IGES writer pairs faces with their name entities in an order that changes
    // from run to run, and regenerated samples must come out byte for byte the same.
    Handle(TDocStd_Document) document = scene_to_xcaf(scene, /*face_names=*/false);
    struct Closer {
      Handle(TDocStd_Document) document;
      ~Closer() { XCAFApp_Application::GetApplication()->Close(document); }
    } closer{document};
    IGESCAFControl_Writer writer;
    Interface_Static::SetCVal("write.iges.unit", "MM");
    Interface_Static::SetIVal("write.iges.brep.mode", 0);
    writer.SetColorMode(true);
    writer.SetNameMode(true);
    writer.SetLayerMode(false);
    if (!writer.Transfer(document)) throw FileError(path + ": IGES write failed: OCCT could not transfer the scene");
    writer.ComputeModel();
    const Handle(IGESData_IGESModel) model = writer.Model();
    IGESData_GlobalSection global = model->GlobalSection();
    const std::string date = iges_date(output_time_stamp());
    global.SetFileName(text(std::filesystem::path(path).filename().string()));
    global.SetSendName(text(std::filesystem::path(path).stem().string()));
    global.SetSystemId(text("cadnurbs"));
    global.SetInterfaceVersion(text("cadnurbs with Open CASCADE IGES processor"));
    global.SetDate(text(date));
    global.SetLastChangeDate(text(date));
    global.SetAuthorName(text(""));
    global.SetCompanyName(text(""));
    model->SetGlobalSection(global);
    std::ostringstream out;
    if (!writer.Write(out)) throw FileError(path + ": IGES write failed: OCCT could not write the file");
    bytes = out.str();
  } catch (const GeometryError& error) {
    throw FileError(path + ": " + error.what());
  } catch (const Standard_Failure& failure) {
    throw FileError(path + ": IGES write failed: " + occt_failure_text(failure));
  }
  write_file_atomically(path, bytes);
}

}  // namespace cadnurbs
