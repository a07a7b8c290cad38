#pragma once
// Reading STEP files (ISO 10303-21: AP203, AP214, AP242 B-rep geometry) into a scene of trimmed NURBS
// surfaces through OCCT's STEP translator and XCAF. No OCCT types.
#include <string>

#include "formats/brep/brep_translation.hpp"
#include "formats/brep/read_stage.hpp"

namespace cadnurbs {

// Takes the path of a STEP file. Returns its assembly tree, names and colours with every face as a trimmed
// NURBS surface, or as a mesh when it cannot be one (listed in fallbacks; see xcaf_to_scene and
// face_to_trimmed_surface); lengths in millimetres, scene.source_unit the file's length unit. A file whose
// names or colours break OCCT's XCAF transfer is read again without them.
// Refuses (FileError, one line "<path>: <cause>"): a missing or empty file; a file without the ISO-10303-21
// header or, truncated, without END-ISO-10303-21 at its end; "STEP read failed: ..." when OCCT cannot read
// it (syntax, or an entity referring to an entity the file lacks: its #number is named) or crashes on it;
// "no shape in the file (K of N roots transferred)"; "no faces in the file".
// `stage` (may be empty) hears each stage of the read as it starts (formats/brep/read_stage.hpp).
BrepTranslation read_step(const std::string& path, const ReadStageListener& stage = {});

}  // namespace cadnurbs
