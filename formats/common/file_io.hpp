#pragma once
// Whole-file reading and atomic writing shared by every format.
#include <stdexcept>
#include <string>

namespace cadnurbs {

// A file that cannot be read or written, or whose content is malformed. what() is one line
// naming the file, the entity or position, and the reason.
class FileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The whole file as bytes. Throws FileError "<path>: cannot open (<reason>)".
std::string read_file(const std::string& path);

// Writes `bytes` to a temporary file beside `path` and renames it over `path`, so an interrupted
// run never leaves a truncated output. Throws FileError on failure (the temporary is removed).
void write_file_atomically(const std::string& path, const std::string& bytes);

// Lower-case extension with the dot (".wrl"), or "" when there is none.
std::string file_extension(const std::string& path);

}  // namespace cadnurbs
