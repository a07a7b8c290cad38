#include "formats/common/file_io.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace cadnurbs {

std::uint64_t regular_file_size(const std::string& path) {
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) throw FileError(path + ": cannot open (" + std::strerror(errno) + ")");
  const auto type = status.st_mode & S_IFMT;
  if (type == S_IFREG) return static_cast<std::uint64_t>(status.st_size);
  if (type == S_IFDIR) throw FileError(path + ": is a directory");
  const char* kind = type == S_IFCHR ? "character device" : type == S_IFBLK ? "block device"
                   : type == S_IFIFO ? "FIFO" : type == S_IFSOCK ? "socket" : "unknown type";
  throw FileError(path + ": not a regular file (" + kind + ")");
}

std::string read_file(const std::string& path) {
  const std::uint64_t size = regular_file_size(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path + ": cannot open (" + std::strerror(errno) + ")");
  std::string bytes(size, '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(size));
  if (in.bad()) throw FileError(path + ": read failed");
  bytes.resize(static_cast<std::size_t>(in.gcount()));  // shorter when the file shrank meanwhile
  return bytes;
}

void write_file_atomically(const std::string& path, const std::function<void(const std::string&)>& write) {
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

void write_file_atomically(const std::string& path, const std::string& bytes) {
  write_file_atomically(path, [&](const std::string& temporary) {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw FileError(path + ": cannot write (" + std::strerror(errno) + ")");
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) throw FileError(path + ": write failed");
  });
}

std::string file_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace cadnurbs
