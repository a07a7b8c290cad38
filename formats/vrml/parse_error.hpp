#pragma once
// The one error form of the VRML/X3D reader: FileError "<file>: line N: <reason>", on one line.
#include <string>

namespace cadnurbs {

// Throws FileError "<file>: line <line>: <reason>"; line breaks and other control characters in the
// reason (quoted file content) become spaces, so the message stays one line.
[[noreturn]] void throw_parse_error(const std::string& file, int line, const std::string& reason);

}  // namespace cadnurbs
