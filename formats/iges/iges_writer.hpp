#pragma once
// Writing a scene as an IGES 5.3 file through OCCT's XCAF IGES writer. No OCCT types.
#include <string>

#include "core/scene.hpp"

namespace cadnurbs {

// Takes an output path and a valid scene. Writes the scene as scene_to_xcaf builds it, each face a trimmed
// surface (entities 144/128/142: OCCT's "Faces" mode, the form most IGES readers take) with the nodes'
// names (not the faces': OCCT writes those in a varying order) and colours, in millimetres, atomically.
// Global section: file name the output's name, system "cadnurbs", dates SOURCE_DATE_EPOCH when set
// (reproducible output, byte for byte), else now.
// Refuses (FileError "<path>: <cause>", one line, nothing written): geometry OCCT cannot hold, a failed
// transfer or write.
void write_iges(const std::string& path, const Scene& scene);

}  // namespace cadnurbs
