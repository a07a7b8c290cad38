#pragma once
// Whole-file reading and atomic writing shared by every format.
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>

namespace cadnurbs {

// A file that cannot be read or written, or whose content is malformed. what() is one line
// naming the file, the entity or position, and the reason.
class FileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The size in bytes of the regular file at `path` (symbolic links followed), looked at before anything
// opens it: a device or FIFO may never end or may block the open, and a directory holds no bytes.
// Throws FileError "<path>: is a directory", "<path>: not a regular file (character device)" (or block
// device, FIFO, socket), or "<path>: cannot open (<reason>)".
std::uint64_t regular_file_size(const std::string& path);

// The whole file as bytes, at most its size when opened (a file growing meanwhile is not followed).
// Refuses what regular_file_size refuses.
std::string read_file(const std::string& path);

// Writes `bytes` to a temporary file beside `path` and renames it over `path`, so an interrupted
// run never leaves a truncated output. Throws FileError on failure (the temporary is removed).
void write_file_atomically(const std::string& path, const std::string& bytes);

// The same for writers that can only write by path (OCCT's): calls write(temporary) with
// temporary = "<path>.tmp<process id>", then renames it to `path`. Whatever `write` throws is passed
// on after the temporary is removed; a failed rename throws FileError "<path>: cannot write (<reason>)".
void write_file_atomically(const std::string& path, const std::function<void(const std::string& temporary)>& write);

// Lower-case extension with the dot (".wrl"), or "" when there is none.
std::string file_extension(const std::string& path);

}  // namespace cadnurbs
