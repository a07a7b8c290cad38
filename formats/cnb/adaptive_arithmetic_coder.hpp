#pragma once
// An adaptive binary arithmetic (range) coder for bytes with contexts: each byte is coded as 8 binary
// decisions down a bit tree, each decision with its own probability per context, adapted after every
// decision by one of two rules (Adaptation, below). The decoder needs the same context sequence, which
// the .cnb reader supplies as it parses. Ours; the carry handling is the classic one of range coders (a
// cached byte plus a count of pending 0xFF bytes).
#include <cstdint>
#include <string>
#include <vector>

#include "formats/cnb/cnb_stream.hpp"

namespace cadnurbs::cnb {

// How a model's probability follows the bits it sees (docs/cnb.md, "The arithmetic coder").
enum class Adaptation : uint8_t {
  // Coders 2 and 3: 12-bit, moving 1/(n+2) of the way after n bits, at least 1/24, within [64, 4032]/4096.
  one_rate,
  // Coder 4 (version 7 on): the mean of a fast estimate (moving at least 1/4 of the way) and a slow one
  // (at least 1/40), 16-bit, within [192, 65344]/65536. A part's payload is a few hundred bytes of fields
  // whose statistics shift from piece to piece: the fast estimate follows a run, the slow one keeps what
  // the file has shown. On the payloads of 180 Phoenix and 226 DFN/QFN parts at 0.01 mm: 6.6% and 6.0%
  // smaller than coder 3 (bench/cnb_coder_prior.cpp, "cost").
  two_rates,
};

// One binary decision's starting model: the probability of a 0 (of 4096) and how many bits it has seen.
struct BitModel {
  uint16_t p = 2048;
  uint8_t seen = 0;
};

// The models every context starts from: 256 per context (node 1 is the first decision of a byte, node
// 2n + bit the next), context_count × 256 in all. `uniform_models()` has them all at ½ (coder 2); coder 3
// (format version 4 on) starts from the coder prior (cnb_coder_prior.hpp).
using ContextModels = std::vector<BitModel>;

// A model as encoder and decoder keep it while coding: for one_rate, `fast` is the 12-bit probability
// and `slow` is unused; for two_rates, both are 16-bit estimates.
struct WorkingModel {
  uint16_t fast, slow;
  uint8_t seen;
};
ContextModels uniform_models();

// `bytes[i]` coded in context `contexts[i]` (< context_count), every context starting from `start`.
std::string arithmetic_encode(const std::string& bytes, const std::vector<uint8_t>& contexts,
                              const ContextModels& start, Adaptation adaptation);

// What coding `bytes` in `contexts` from `start` costs in each context, in bits: -log2 of each decision's
// probability as the encoder meets it, summed (context_count entries). The contexts' models adapt apart,
// so the sum is the coded size less the range coder's few bytes of flush: where a payload's bytes go.
std::vector<double> arithmetic_cost_by_context(const std::string& bytes, const std::vector<uint8_t>& contexts,
                                               const ContextModels& start, Adaptation adaptation);

// Decodes lazily. Past the end of the coded bytes it reads zeros: the caller bounds how many bytes it
// asks for (the payload size in the header), and the checksum has vouched for the coded bytes.
class ArithmeticDecoder : public ByteSource {
 public:
  // `start` and `adaptation`: the models the encoder started from and its rule.
  ArithmeticDecoder(const char* coded, size_t size, const ContextModels& start, Adaptation adaptation);
  uint8_t next(int context) override;

 private:
  uint8_t input();
  bool bit(WorkingModel& model);
  const char* coded_;
  size_t size_, position_ = 0;
  uint32_t range_ = 0xFFFFFFFFu, code_ = 0;
  Adaptation adaptation_;
  std::vector<WorkingModel> models_;
};

// How many decoded bytes one coded byte can at most stand for: bounds what a header may claim before
// anything is allocated. one_rate keeps probabilities within [64, 4032]/4096, so a decision costs at least
// -log2(4032/4096) = 0.023 bits and a byte 0.18 bits (at most 44 bytes per coded byte); two_rates within
// [192, 65344]/65536, at least 0.0042 bits a decision and 0.034 a byte (at most 237).
constexpr size_t arithmetic_expansion_limit(Adaptation adaptation) {
  return adaptation == Adaptation::one_rate ? 64 : 256;
}

}  // namespace cadnurbs::cnb
