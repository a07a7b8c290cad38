#pragma once
// Reads a .cnb file (docs/cnb.md) back into a scene.
#include <cstdint>
#include <string>
#include <vector>

#include "core/scene.hpp"

namespace cadnurbs {

// The scene from the file's bytes. Refuses damaged or truncated input with one FileError line,
// "<name>: byte N: <reason>" for the file's header and checksum, "<name>: decoded byte N: <reason>" for
// the payload behind them (N counted in the decoded payload), never allocating more than the remaining
// bytes can hold. Every decoded shape is validated (an invalid one is refused the same way). `facts`, when
// given, receives what the scene header says of the file's accuracy.
struct CnbFileFacts {
  double asked_deviation = 0;  // D, the deviation the writer was asked for (scene units)
  double deviation_bound = 0;  // the bound it reached: every point of the file within it of the part written
};
Scene read_cnb(const std::string& bytes, const std::string& name, CnbFileFacts* facts = nullptr);

// The decoded payload of a file as read_cnb parses it: each byte and the coder context it is read in
// (docs/cnb.md, "The arithmetic coder"), for tools that study or train the coder
// (bench/cnb_coder_prior.cpp). Refuses what read_cnb refuses, in the same words.
struct CnbPayload {
  std::string bytes;
  std::vector<uint8_t> contexts;  // one per byte
  uint8_t version = 0;            // the file's format version
  bool arithmetic = false;        // whether the file was arithmetic-coded (else deflated)
};
CnbPayload read_cnb_payload(const std::string& bytes, const std::string& name);

}  // namespace cadnurbs
