#include "formats/step/step_writer.hpp"

#include <APIHeaderSection_MakeHeader.hxx>
#include <Interface_Static.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <STEPControl_Writer.hxx>
#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>
#include <StepData_StepModel.hxx>
#include <TCollection_HAsciiString.hxx>
#include <XCAFApp_Application.hxx>
#include <filesystem>

#include "core/geometry_error.hpp"
#include "formats/brep/occt_errors.hpp"
#include "formats/brep/occt_setup.hpp"
#include "formats/brep/output_time_stamp.hpp"
#include "formats/brep/scene_to_xcaf.hpp"
#include "formats/common/file_io.hpp"

namespace cadnurbs {

void write_step(const std::string& path, const Scene& scene) {
  prepare_occt();
  Handle(TDocStd_Document) document;
  try {
    validate(scene);
    OCC_CATCH_SIGNALS
    document = scene_to_xcaf(scene);
  } catch (const GeometryError& error) {
    throw FileError(path + ": " + error.what());
  } catch (const Standard_Failure& failure) {
    throw FileError(path + ": STEP write failed: " + occt_failure_text(failure));
  }
  struct Closer {
    Handle(TDocStd_Document) document;
    ~Closer() { XCAFApp_Application::GetApplication()->Close(document); }
  } closer{document};

  write_file_atomically(path, [&](const std::string& temporary) {
    try {
      OCC_CATCH_SIGNALS
      STEPCAFControl_Writer writer;
      Interface_Static::SetCVal("write.step.unit", "MM");
      Interface_Static::SetCVal("write.step.schema", "AP214IS");
      writer.SetColorMode(true);
      writer.SetNameMode(true);
      writer.SetLayerMode(false);
      writer.SetPropsMode(false);
      if (!writer.Transfer(document, STEPControl_AsIs))
        throw FileError(path + ": STEP write failed: OCCT could not transfer the scene");
      APIHeaderSection_MakeHeader header(writer.ChangeWriter().Model());
      header.SetName(new TCollection_HAsciiString(std::filesystem::path(path).filename().string().c_str()));
      header.SetDescriptionValue(1, new TCollection_HAsciiString("cadnurbs scene"));
      header.SetTimeStamp(new TCollection_HAsciiString(output_time_stamp().c_str()));
      header.SetOriginatingSystem(new TCollection_HAsciiString("cadnurbs"));
      header.SetPreprocessorVersion(new TCollection_HAsciiString("cadnurbs with Open CASCADE STEP translator"));
      header.SetAuthorisation(new TCollection_HAsciiString(""));
      header.SetAuthorValue(1, new TCollection_HAsciiString(""));
      header.SetOrganizationValue(1, new TCollection_HAsciiString(""));
      if (writer.Write(temporary.c_str()) != IFSelect_RetDone)
        throw FileError(path + ": STEP write failed: OCCT could not write the file");
    } catch (const Standard_Failure& failure) {
      throw FileError(path + ": STEP write failed: " + occt_failure_text(failure));
    }
  });
}

}  // namespace cadnurbs
