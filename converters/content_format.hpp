#pragma once
// Which input format a file holds, told by its first bytes rather than its name: a library folder holds
// files whose extensions lie (a STEP file saved as .stl, no extension at all). batch uses it to find
// parts; the format then reads the file whatever its name.
#include <string>

#include "converters/file_formats.hpp"

namespace cadnurbs {

// Takes a path. Returns the input format its content shows, or null when no signature matches:
// STEP ("ISO-10303-21;"), IGES (an 80-column first line marked 'S' in column 73), VRML97 ("#VRML V2.0"),
// X3D classic ("#X3D V"), X3D XML ("<X3D" in the first 1 KiB), gzip'd VRML/X3D (gzip's magic number, with
// the file name saying which; null when it names no input format), Rhino .3dm ("3D Geometry File Format "), .cnb
// ("\x89CNB"), binary STL (84 + 50 x its triangle count bytes), ASCII STL ("solid").
// Leading whitespace and a UTF-8 byte-order mark are skipped for the text formats.
// Throws FileError for what regular_file_size refuses (directories, devices, FIFOs).
const FileFormat* format_by_content(const std::string& path);

}  // namespace cadnurbs
