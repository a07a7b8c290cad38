#pragma once
// What the STEP and IGES readers share around OCCT's translators (formats/step, formats/iges): the
// roots transferred without XCAF, and the order "XCAF first, geometry only if XCAF fails".
#include <TopoDS_Shape.hxx>
#include <XSControl_Reader.hxx>

#include <functional>
#include <optional>
#include <string>

#include "formats/brep/brep_translation.hpp"
#include "formats/brep/read_stage.hpp"

namespace cadnurbs {

// True when the shape holds at least one face.
bool has_faces(const TopoDS_Shape& shape);

// Transfers every root of a reader whose file is already read (telling `stage` "transfer"); throws
// FileError naming `path` when there is no root, nothing transferred, or no face.
TopoDS_Shape transfer_roots(XSControl_Reader& reader, const std::string& path, const ReadStageListener& stage);

// with_xcaf() (nullopt: the document has no faces), then plain() when XCAF found none or failed (damaged
// style or name entities can crash the XCAF transfer while the geometry still reads). OCCT failures of
// both become one FileError "<path>: <format> read failed: <reason>".
BrepTranslation read_xcaf_or_plain(const std::string& path, const std::string& format,
                                   const std::function<std::optional<BrepTranslation>()>& with_xcaf,
                                   const std::function<BrepTranslation()>& plain);

}  // namespace cadnurbs
