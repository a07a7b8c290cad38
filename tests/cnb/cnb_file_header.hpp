#pragma once
// The header fields of a .cnb file of version 2 on (docs/cnb.md, "File header"), for tests that damage or
// rewrite them: the payload size's varuint at byte 6, then the CRC-32 of all before it and of the coded
// bytes. And what the reader says of such a file.
#include <zlib.h>

#include <cstdint>
#include <string>

#include "formats/cnb/cnb_reader.hpp"
#include "formats/common/file_io.hpp"

namespace cadnurbs {

// Where the header's CRC-32 lies: after the payload size's varuint at byte 6.
inline size_t crc_offset(const std::string& file) {
  size_t at = 6;
  while (static_cast<uint8_t>(file[at]) & 0x80) ++at;
  return at + 1;
}

// The file with its payload size replaced by `size` and its CRC made right again.
inline std::string with_payload_size(const std::string& file, uint64_t size) {
  const size_t crc_at = crc_offset(file);
  std::string out = file.substr(0, 6);
  for (uint64_t v = size;; v >>= 7) {
    out.push_back(static_cast<char>((v & 0x7F) | (v >= 0x80 ? 0x80 : 0)));
    if (v < 0x80) break;
  }
  const std::string coded = file.substr(crc_at + 4);
  uLong c = crc32(0L, reinterpret_cast<const Bytef*>(out.data()), static_cast<uInt>(out.size()));
  c = crc32(c, reinterpret_cast<const Bytef*>(coded.data()), static_cast<uInt>(coded.size()));
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>(c >> (8 * i)));
  return out + coded;
}

inline uint64_t payload_size(const std::string& file) {
  uint64_t v = 0;
  for (size_t at = 6, shift = 0;; ++at, shift += 7) {
    v |= static_cast<uint64_t>(static_cast<uint8_t>(file[at]) & 0x7F) << shift;
    if (!(static_cast<uint8_t>(file[at]) & 0x80)) return v;
  }
}

// The file with its version byte set to `version` and its CRC made right again.
inline std::string with_version(std::string file, uint8_t version) {
  file[4] = static_cast<char>(version);
  return with_payload_size(file, payload_size(file));
}

// The reader's one-line refusal of `file` read as `name`, or "(read without error)".
inline std::string read_error(const std::string& file, const std::string& name) {
  try {
    read_cnb(file, name);
  } catch (const FileError& e) {
    return e.what();
  }
  return "(read without error)";
}

}  // namespace cadnurbs
