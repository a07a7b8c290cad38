#include "formats/brep/reader_plumbing.hpp"

#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>

#include "formats/brep/occt_errors.hpp"
#include "formats/brep/read_stage.hpp"
#include "formats/common/file_io.hpp"

namespace cadnurbs {

bool has_faces(const TopoDS_Shape& shape) { return !shape.IsNull() && TopExp_Explorer(shape, TopAbs_FACE).More(); }

TopoDS_Shape transfer_roots(XSControl_Reader& reader, const std::string& path, const ReadStageListener& stage) {
  const int roots = reader.NbRootsForTransfer();
  if (roots == 0) throw FileError(path + ": no shape in the file (no transferable roots)");
  tell_stage(stage, "transfer");
  const int transferred = reader.TransferRoots();
  const TopoDS_Shape shape = reader.OneShape();
  if (transferred == 0 || shape.IsNull())
    throw FileError(path + ": no shape in the file (" + std::to_string(transferred) + " of " + std::to_string(roots) +
                    " roots transferred)");
  if (!has_faces(shape))
    throw FileError(path + ": no faces in the file (" + std::to_string(transferred) + " of " + std::to_string(roots) +
                    " roots transferred, none with faces)");
  return shape;
}

BrepTranslation read_xcaf_or_plain(const std::string& path, const std::string& format,
                                   const std::function<std::optional<BrepTranslation>()>& with_xcaf,
                                   const std::function<BrepTranslation()>& plain) {
  std::string xcaf_failure;
  try {
    OCC_CATCH_SIGNALS
    if (auto translation = with_xcaf()) return std::move(*translation);
  } catch (const Standard_Failure& failure) {
    xcaf_failure = occt_failure_text(failure);
  }
  try {
    OCC_CATCH_SIGNALS
    return plain();
  } catch (const Standard_Failure& failure) {
    throw FileError(path + ": " + format + " read failed: " +
                    (xcaf_failure.empty() ? occt_failure_text(failure) : xcaf_failure));
  }
}

}  // namespace cadnurbs
