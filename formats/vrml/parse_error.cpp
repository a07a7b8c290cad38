#include "formats/vrml/parse_error.hpp"

#include "formats/common/file_io.hpp"

namespace cadnurbs {

void throw_parse_error(const std::string& file, int line, const std::string& reason) {
  std::string message = file + ": line " + std::to_string(line) + ": " + reason;
  for (char& c : message)
    if (static_cast<unsigned char>(c) < 0x20) c = ' ';
  throw FileError(message);
}

}  // namespace cadnurbs
