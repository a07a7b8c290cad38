#pragma once
// The .cnb file around the payload (docs/cnb.md, "File header"): magic, version, entropy coder, sizes and
// a CRC-32, then the coded payload (raw deflate, or our adaptive arithmetic coder).
#include <memory>
#include <string>

#include "formats/cnb/cnb_options.hpp"
#include "formats/cnb/cnb_stream.hpp"

namespace cadnurbs::cnb {

// Versions 4 to 6 (6 written; docs/cnb.md says what each adds to the payload): magic, version, coder, the payload size as a varuint, the CRC-32, the coded bytes.
// Version 3 (still read): the same, without coder 3 (the coder prior) and without the contexts of mesh
// symbols by the symbol before and of vertex coordinates by axis. Version 2 (still read): the same header;
// its scene header's grid step and bound are raw float64 where version 3 has exact numbers. Version 1
// (still read): a fixed 18-byte header with the coded size; its scene header's numbers are all raw
// float64 (docs/cnb.md).
constexpr size_t version_1_header_size = 18;

// The whole file for a payload of format version `version`, coded as `choice` asks (the smallest for
// Coder::smallest). Fills the report's size fields.
std::string pack(const ByteWriter& payload, CnbOptions::Coder choice, CnbWriteReport* report,
                 uint8_t version = format_version);

struct OpenedPayload {
  std::unique_ptr<ByteSource> source;  // yields the decoded payload byte by byte
  size_t size = 0;                     // decoded payload bytes the header promises
  uint8_t version = format_version;    // of the file: the payload's layout depends on it
  bool arithmetic = false;             // coded by the arithmetic coder (else deflated)
};

// Checks the header, the length and the CRC before decoding anything. Throws FileError
// "<name>: byte N: <reason>" naming the first byte that is wrong (or the header field that disagrees
// with the rest of the file).
OpenedPayload open_payload(const std::string& file, const std::string& name);

}  // namespace cadnurbs::cnb
