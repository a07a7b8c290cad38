#pragma once
// openNURBS's compressed buffer (ON_BinaryArchive::WriteCompressedBuffer): uint32 inflated size; when not
// zero, the CRC-32 of the inflated bytes (uint32), a method byte, then either the bytes as they are
// (method 0) or a TCODE_ANONYMOUS_CHUNK holding a zlib stream (method 1).
#include <cstddef>
#include <string>

#include "formats/3dm/archive_reader.hpp"

namespace cadnurbs::rhino {

// Reads one compressed buffer whose inflated size must be `expected_size` (the caller knows it from its
// counts, e.g. vertex count * 12) or 0 (openNURBS's form of an absent array). Returns the inflated bytes
// ("" for an absent array). Refused, before anything is allocated: a declared size other than those, a method other than 0 or 1, a zlib stream too short to inflate
// to the declared size (deflate cannot shrink data more than 1032:1); then a stream that ends early, runs
// long or is corrupt, and a CRC mismatch. `what` names the buffer in messages ("vertex buffer").
std::string read_compressed_buffer(ArchiveReader& reader, std::size_t expected_size, const std::string& what);

// Moves past one compressed buffer without inflating it.
void skip_compressed_buffer(ArchiveReader& reader);

}  // namespace cadnurbs::rhino
