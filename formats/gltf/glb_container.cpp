#include "formats/gltf/glb_container.hpp"

#include <cstdint>
#include <limits>
#include <stdexcept>

namespace cadnurbs {
namespace {

void append_uint32(std::string& out, std::uint64_t value) {
  for (int byte = 0; byte < 4; ++byte) out += static_cast<char>((value >> (8 * byte)) & 0xff);
}

std::size_t padded(std::size_t size) { return (size + 3) / 4 * 4; }

}  // namespace

std::string glb_container(const std::string& json, const std::string& bin) {
  const std::size_t json_length = padded(json.size());
  const std::size_t bin_length = padded(bin.size());
  const std::size_t total = 12 + 8 + json_length + (bin.empty() ? 0 : 8 + bin_length);
  if (total > std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("glTF binary: " + std::to_string(total) + " bytes exceed the 4 GiB limit of the format");
  std::string out;
  out.reserve(total);
  out += "glTF";
  append_uint32(out, 2);
  append_uint32(out, total);
  append_uint32(out, json_length);
  out += "JSON";
  out += json;
  out.append(json_length - json.size(), ' ');
  if (!bin.empty()) {
    append_uint32(out, bin_length);
    out.append("BIN\0", 4);
    out += bin;
    out.append(bin_length - bin.size(), '\0');
  }
  return out;
}

}  // namespace cadnurbs
