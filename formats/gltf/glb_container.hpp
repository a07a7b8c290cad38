#pragma once
// The GLB container of glTF 2.0 (the spec's "Binary glTF Layout"): a 12-byte header, the JSON chunk
// padded with spaces and the BIN chunk padded with zeros, each to a multiple of 4 bytes, little-endian.
#include <string>

namespace cadnurbs {

// The .glb bytes holding `json` and, unless it is empty, `bin` (buffer 0 of the JSON, whose byteLength
// must be bin.size()). Refuses (std::length_error) a total beyond the format's 32-bit length.
std::string glb_container(const std::string& json, const std::string& bin);

}  // namespace cadnurbs
