#pragma once
// An adaptive binary arithmetic (range) coder for bytes with contexts: each byte is coded as 8 binary
// decisions down a bit tree, each decision with its own probability per context, adapted after every
// decision (12-bit probabilities, moving 1/(n+2) of the way after n bits, at least 1/24, never nearer to 0 or 1 than 64/4096). The decoder needs the same context sequence,
// which the .cnb reader supplies as it parses. Ours; the carry handling is the classic one of range coders
// (a cached byte plus a count of pending 0xFF bytes).
#include <cstdint>
#include <string>
#include <vector>

#include "formats/cnb/cnb_stream.hpp"

namespace cadnurbs::cnb {

// One binary decision's model: the probability of a 0 (of 4096) and how many bits it has seen.
struct BitModel {
  uint16_t p = 2048;
  uint8_t seen = 0;
};

// The models every context starts from: 256 per context (node 1 is the first decision of a byte, node
// 2n + bit the next), context_count × 256 in all. `uniform_models()` has them all at ½ (coder 2); coder 3
// (format version 4 on) starts from the coder prior (cnb_coder_prior.hpp).
using ContextModels = std::vector<BitModel>;
ContextModels uniform_models();

// `bytes[i]` coded in context `contexts[i]` (< context_count), every context starting from `start`.
std::string arithmetic_encode(const std::string& bytes, const std::vector<uint8_t>& contexts,
                              const ContextModels& start);

// Decodes lazily. Past the end of the coded bytes it reads zeros: the caller bounds how many bytes it
// asks for (the payload size in the header), and the checksum has vouched for the coded bytes.
class ArithmeticDecoder : public ByteSource {
 public:
  // `start`: the models the encoder started from.
  ArithmeticDecoder(const char* coded, size_t size, ContextModels start);
  uint8_t next(int context) override;

 private:
  uint8_t input();
  bool bit(BitModel& model);
  const char* coded_;
  size_t size_, position_ = 0;
  uint32_t range_ = 0xFFFFFFFFu, code_ = 0;
  std::vector<BitModel> probabilities_;
};

// How many decoded bytes one coded byte can at most stand for (probabilities are kept within
// [64, 4032]/4096, so each decision costs at least -log2(4032/4096) = 0.023 bits and a byte 0.18 bits:
// at most 44 bytes per coded byte): bounds what a header may claim before anything is allocated.
constexpr size_t arithmetic_expansion_limit = 64;

}  // namespace cadnurbs::cnb
