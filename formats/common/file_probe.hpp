#pragma once
// A look at the first and last bytes of a file, for cheap format checks before a reader parses it all.
#include <cstddef>
#include <string>

namespace cadnurbs {

// Up to `count` bytes from the start of the file ("" for an empty file).
// Refuses what regular_file_size (file_io.hpp) refuses.
std::string file_head(const std::string& path, std::size_t count);

// Up to `count` bytes from the end of the file. Same refusal.
std::string file_tail(const std::string& path, std::size_t count);

}  // namespace cadnurbs
