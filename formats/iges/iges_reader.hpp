#pragma once
// Reading IGES files (trimmed surfaces 144/128/142, B-rep solids 186/514/510, and the surface types OCCT
// translates) into a scene of trimmed NURBS surfaces through OCCT's IGES translator and XCAF. No OCCT types.
#include <string>

#include "formats/brep/brep_translation.hpp"
#include "formats/brep/read_stage.hpp"

namespace cadnurbs {

// Takes the path of an IGES file. Returns its shapes, names and colours with every face as a trimmed NURBS
// surface, or as a mesh when it cannot be one (listed in fallbacks); lengths in millimetres,
// scene.source_unit the unit of the file's global section. A file whose names or colours break OCCT's
// XCAF transfer is read again without them.
// Refuses (FileError, one line "<path>: <cause>"): a missing or empty file; a file whose first line is not
// an 80-column Start (or Flag) section line; a truncated file (no Terminate section at its end); a damaged
// one (section line counts other than its Terminate line says); "IGES read failed: ..." when OCCT cannot
// read it or crashes on it, or an entity points to one the file lacks;
// "no shape in the file (K of N roots transferred)"; "no faces in the file".
// `stage` (may be empty) hears each stage of the read as it starts (formats/brep/read_stage.hpp).
BrepTranslation read_iges(const std::string& path, const ReadStageListener& stage = {});

}  // namespace cadnurbs
