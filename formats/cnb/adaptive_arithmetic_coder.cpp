#include "formats/cnb/adaptive_arithmetic_coder.hpp"

#include <algorithm>
#include <utility>

namespace cadnurbs::cnb {

namespace {

constexpr int probability_bits = 12;
constexpr uint16_t one = 1u << probability_bits;
// A probability moves 1/(n+2) of the way towards each bit it sees, n the bits seen so far, until that
// is 1/slowest: fast learning from few bits (files are small), then a stable estimate.
constexpr int slowest = 24;
constexpr uint32_t top = 1u << 24;
// Probabilities stay within [min, one - min] so that no decision is ever free.
constexpr uint16_t min_probability = 64;

void adapt(BitModel& m, bool bit) {
  const int target = bit ? 0 : one;  // p is the probability of a 0
  int p = m.p + (target - m.p) / (m.seen + 2);
  if (m.seen + 2 < slowest) ++m.seen;
  m.p = static_cast<uint16_t>(std::clamp<int>(p, min_probability, one - min_probability));
}

class Encoder {
 public:
  void bit(BitModel& m, bool b) {
    const uint32_t bound = (range_ >> probability_bits) * m.p;
    if (!b) range_ = bound;
    else { low_ += bound; range_ -= bound; }
    adapt(m, b);
    while (range_ < top) { range_ <<= 8; shift_low(); }
  }
  std::string finish() {
    for (int i = 0; i < 5; ++i) shift_low();
    return out_;
  }

 private:
  // Emits the top byte of low_, holding back 0xFF bytes until a carry into them is settled.
  void shift_low() {
    if (low_ < 0xFF000000u || low_ > 0xFFFFFFFFu) {
      const uint8_t carry = static_cast<uint8_t>(low_ >> 32);
      if (started_) out_.push_back(static_cast<char>(cache_ + carry));
      for (; pending_ > 0; --pending_) out_.push_back(static_cast<char>(0xFF + carry));
      cache_ = static_cast<uint8_t>(low_ >> 24);
      started_ = true;
    } else {
      ++pending_;
    }
    low_ = (low_ & 0x00FFFFFFu) << 8;
  }
  uint64_t low_ = 0;
  uint32_t range_ = 0xFFFFFFFFu;
  uint8_t cache_ = 0;
  bool started_ = false;
  size_t pending_ = 0;
  std::string out_;
};

}  // namespace

ContextModels uniform_models() { return ContextModels(static_cast<size_t>(context_count) * 256); }

std::string arithmetic_encode(const std::string& bytes, const std::vector<uint8_t>& contexts,
                              const ContextModels& start) {
  ContextModels probabilities = start;
  Encoder encoder;
  for (size_t i = 0; i < bytes.size(); ++i) {
    BitModel* tree = &probabilities[static_cast<size_t>(contexts[i]) * 256];
    const uint8_t value = static_cast<uint8_t>(bytes[i]);
    unsigned node = 1;
    for (int b = 7; b >= 0; --b) {
      const bool bit = (value >> b) & 1;
      encoder.bit(tree[node], bit);
      node = 2 * node + bit;
    }
  }
  return encoder.finish();
}

ArithmeticDecoder::ArithmeticDecoder(const char* coded, size_t size, ContextModels start)
    : coded_(coded), size_(size), probabilities_(std::move(start)) {
  for (int i = 0; i < 4; ++i) code_ = (code_ << 8) | input();
}

uint8_t ArithmeticDecoder::input() { return position_ < size_ ? static_cast<uint8_t>(coded_[position_++]) : 0; }

bool ArithmeticDecoder::bit(BitModel& m) {
  const uint32_t bound = (range_ >> probability_bits) * m.p;
  bool b;
  if (code_ < bound) { range_ = bound; b = false; }
  else { code_ -= bound; range_ -= bound; b = true; }
  adapt(m, b);
  while (range_ < top) { range_ <<= 8; code_ = (code_ << 8) | input(); }
  return b;
}

uint8_t ArithmeticDecoder::next(int context) {
  BitModel* tree = &probabilities_[static_cast<size_t>(context) * 256];
  unsigned node = 1;
  for (int b = 0; b < 8; ++b) node = 2 * node + (bit(tree[node]) ? 1 : 0);
  return static_cast<uint8_t>(node - 256);
}

}  // namespace cadnurbs::cnb
