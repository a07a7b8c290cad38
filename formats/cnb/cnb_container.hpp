#pragma once
// The .cnb file around the payload (docs/cnb.md, "File header"): magic, version, entropy coder, sizes and
// a CRC-32, then the coded payload (raw deflate, or our adaptive arithmetic coder).
#include <memory>
#include <string>

#include "formats/cnb/cnb_options.hpp"
#include "formats/cnb/cnb_stream.hpp"

namespace cadnurbs::cnb {

constexpr size_t header_size = 18;
constexpr uint8_t format_version = 1;

// The whole file for a payload, coded as `choice` asks (the smaller of both for Coder::smallest).
// Fills the report's size fields.
std::string pack(const ByteWriter& payload, CnbOptions::Coder choice, CnbWriteReport* report);

struct OpenedPayload {
  std::unique_ptr<ByteSource> source;  // yields the decoded payload byte by byte
  size_t size = 0;                     // decoded payload bytes the header promises
};

// Checks the header, the length and the CRC before decoding anything. Throws FileError
// "<name>: byte N: <reason>" naming the first byte that is wrong (or the header field that disagrees
// with the rest of the file).
OpenedPayload open_payload(const std::string& file, const std::string& name);

}  // namespace cadnurbs::cnb
