#include "formats/common/file_probe.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>

#include "formats/common/file_io.hpp"

namespace cadnurbs {

namespace {

std::ifstream open(const std::string& path) {
  regular_file_size(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path + ": cannot open (" + std::strerror(errno) + ")");
  return in;
}

std::string read_some(std::ifstream& in, std::size_t count) {
  std::string out(count, '\0');
  in.read(out.data(), static_cast<std::streamsize>(count));
  out.resize(static_cast<std::size_t>(in.gcount()));
  return out;
}

}  // namespace

std::string file_head(const std::string& path, std::size_t count) {
  std::ifstream in = open(path);
  return read_some(in, count);
}

std::string file_tail(const std::string& path, std::size_t count) {
  std::ifstream in = open(path);
  in.seekg(0, std::ios::end);
  const auto size = static_cast<std::size_t>(in.tellg());
  in.seekg(static_cast<std::streamoff>(size > count ? size - count : 0));
  return read_some(in, count);
}

}  // namespace cadnurbs
