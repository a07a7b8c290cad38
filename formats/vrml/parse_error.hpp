#pragma once
// The one error form of the VRML/X3D reader: FileError "<file>: line N: <reason>", on one line.
#include <string>

#include "formats/common/file_io.hpp"

namespace cadnurbs {

// Throws FileError "<file>: line <line>: <reason>"; line breaks and other control characters in the
// reason (quoted file content) become spaces, so the message stays one line.
[[noreturn]] inline void throw_parse_error(const std::string& file, int line, const std::string& reason) {
  std::string message = file + ": line " + std::to_string(line) + ": " + reason;
  for (char& c : message)
    if (static_cast<unsigned char>(c) < 0x20) c = ' ';
  throw FileError(message);
}

}  // namespace cadnurbs
