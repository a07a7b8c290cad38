#pragma once
// Writing a scene as a STEP file (AP214) through OCCT's XCAF STEP writer. No OCCT types.
#include <string>

#include "core/scene.hpp"

namespace cadnurbs {

// Takes an output path and a valid scene. Writes the scene as scene_to_xcaf builds it (trimmed surfaces as
// faces sewn into shells, closed shells as solids; assemblies, names, colours) in millimetres, atomically
// (a temporary beside `path`, then renamed). Header: FILE_NAME is the file's name, the originating system
// "cadnurbs", the time stamp SOURCE_DATE_EPOCH when that is set (reproducible output), else now (UTC).
// Refuses (FileError "<path>: <cause>", one line, nothing written): geometry OCCT cannot hold, a failed
// transfer or write.
void write_step(const std::string& path, const Scene& scene);

}  // namespace cadnurbs
