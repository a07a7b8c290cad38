#include "converters/content_format.hpp"

#include <cstdint>
#include <cstring>
#include <string_view>

#include "formats/common/file_io.hpp"
#include "formats/common/file_probe.hpp"

namespace cadnurbs {

namespace {

// The text after a UTF-8 byte-order mark and leading whitespace.
std::string_view text_start(std::string_view head) {
  if (head.substr(0, 3) == "\xEF\xBB\xBF") head.remove_prefix(3);
  while (!head.empty() && std::strchr(" \t\r\n", head.front())) head.remove_prefix(1);
  return head;
}

bool starts(std::string_view head, std::string_view signature) { return text_start(head).substr(0, signature.size()) == signature; }

bool iges_start(std::string_view head) {
  const size_t end = head.find_first_of("\r\n");
  return end == 80 && head[72] == 'S';  // the Start section: 80 columns, 'S' in column 73
}

bool binary_stl(std::string_view head, std::uintmax_t size) {
  if (head.size() < 84) return false;
  std::uint32_t count;
  std::memcpy(&count, head.data() + 80, 4);  // little-endian on every machine cadnurbs builds for
  return size == 84 + 50 * static_cast<std::uintmax_t>(count);
}

struct Signature {
  const char* extension;  // the format's usual extension (file_formats.hpp's table)
  bool (*matches)(std::string_view head, std::uintmax_t size);
};

// In order: binary STL before ASCII STL (a binary header may start with "solid").
const Signature kSignatures[] = {
    {".step", [](std::string_view h, std::uintmax_t) { return starts(h, "ISO-10303-21;"); }},
    {".iges", [](std::string_view h, std::uintmax_t) { return iges_start(h); }},
    {".wrl", [](std::string_view h, std::uintmax_t) { return starts(h, "#VRML V2.0"); }},
    {".x3dv", [](std::string_view h, std::uintmax_t) { return starts(h, "#X3D V"); }},
    {".x3d", [](std::string_view h, std::uintmax_t) { return h.find("<X3D") != std::string_view::npos; }},
    {".3dm", [](std::string_view h, std::uintmax_t) { return h.substr(0, 24) == "3D Geometry File Format "; }},
    {".cnb", [](std::string_view h, std::uintmax_t) { return h.substr(0, 4) == "\x89" "CNB"; }},
    {".stl", [](std::string_view h, std::uintmax_t size) { return binary_stl(h, size); }},
    {".stl", [](std::string_view h, std::uintmax_t) { return starts(h, "solid"); }},
};

bool gzip_magic(std::string_view head) { return head.substr(0, 2) == "\x1f\x8b"; }

}  // namespace

const FileFormat* format_by_content(const std::string& path) {
  const std::uintmax_t size = regular_file_size(path);
  const std::string head = file_head(path, 1024);
  if (gzip_magic(head)) {
    const FileFormat* named = format_of(path);
    return named && named->read ? named : nullptr;  // gzip'd VRML/X3D: its name says which
  }
  for (const Signature& signature : kSignatures)
    if (signature.matches(head, size)) return format_of(std::string("x") + signature.extension);
  return nullptr;
}

}  // namespace cadnurbs
