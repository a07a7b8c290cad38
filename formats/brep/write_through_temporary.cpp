#include "formats/brep/write_through_temporary.hpp"

#include <unistd.h>

#include <filesystem>
#include <system_error>

#include "formats/common/file_io.hpp"

namespace cadnurbs {

void write_through_temporary(const std::string& path, const std::function<void(const std::string&)>& write) {
  const std::string temporary = path + ".tmp" + std::to_string(::getpid());
  std::error_code ignored;
  try {
    write(temporary);
  } catch (...) {
    std::filesystem::remove(temporary, ignored);
    throw;
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::filesystem::remove(temporary, ignored);
    throw FileError(path + ": cannot write (" + error.message() + ")");
  }
}

}  // namespace cadnurbs
