#pragma once
// A look at the first and last bytes of a file, for cheap format checks before a reader parses it all.
#include <cstddef>
#include <string>

namespace cadnurbs {

// Up to `count` bytes from the start of the file ("" for an empty file).
// Throws FileError "<path>: cannot open (<reason>)".
std::string file_head(const std::string& path, std::size_t count);

// Up to `count` bytes from the end of the file. Same refusal.
std::string file_tail(const std::string& path, std::size_t count);

}  // namespace cadnurbs
