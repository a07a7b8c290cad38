#include "formats/cnb/adaptive_arithmetic_coder.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace cadnurbs::cnb {

namespace {

constexpr uint32_t top = 1u << 24;

// one_rate: a probability moves 1/(n+2) of the way towards each bit it sees, n the bits seen so far,
// until that is 1/24: fast learning from few bits (files are small), then a stable estimate. It stays
// within [64, 4096 - 64] so that no decision is ever free.
namespace one_rate {
constexpr int bits = 12, one = 1 << bits, slowest = 24, least = 64;
}
// two_rates: the same step for each estimate, down to 1/4 for the fast one and 1/40 for the slow one;
// their mean, kept within [192, 65536 - 192], is the probability.
namespace two_rates {
constexpr int bits = 16, one = 1 << bits, fastest_limit = 4, slowest = 40, least = 192;
}

int probability_bits(Adaptation a) { return a == Adaptation::one_rate ? one_rate::bits : two_rates::bits; }

// The probability of a 0, of 2^probability_bits.
uint32_t probability(const WorkingModel& m, Adaptation a) {
  if (a == Adaptation::one_rate) return m.fast;
  return static_cast<uint32_t>(std::clamp((m.fast + m.slow) >> 1, two_rates::least, two_rates::one - two_rates::least));
}

void adapt(WorkingModel& m, bool bit, Adaptation a) {
  const int n = m.seen + 2;
  if (a == Adaptation::one_rate) {
    using namespace one_rate;
    const int target = bit ? 0 : one;  // p is the probability of a 0
    const int p = m.fast + (target - m.fast) / n;
    if (n < slowest) ++m.seen;
    m.fast = static_cast<uint16_t>(std::clamp<int>(p, least, one - least));
    return;
  }
  using namespace two_rates;
  const int target = bit ? 0 : one;
  // Each step is at most half the way (n >= 2), so neither estimate reaches `one` nor falls below 0.
  m.fast = static_cast<uint16_t>(m.fast + (target - m.fast) / std::min(n, fastest_limit));
  m.slow = static_cast<uint16_t>(m.slow + (target - m.slow) / std::min(n, slowest));
  if (n < slowest) ++m.seen;
}

std::vector<WorkingModel> working_models(const ContextModels& start, Adaptation a) {
  std::vector<WorkingModel> models(start.size());
  const int scale = a == Adaptation::one_rate ? 0 : two_rates::bits - one_rate::bits;
  for (size_t i = 0; i < start.size(); ++i) {
    const auto p = static_cast<uint16_t>(start[i].p << scale);
    models[i] = {p, p, start[i].seen};
  }
  return models;
}

class Encoder {
 public:
  explicit Encoder(Adaptation adaptation) : adaptation_(adaptation), bits_(probability_bits(adaptation)) {}
  void bit(WorkingModel& m, bool b) {
    const uint32_t bound = (range_ >> bits_) * probability(m, adaptation_);
    if (!b) range_ = bound;
    else { low_ += bound; range_ -= bound; }
    adapt(m, b, adaptation_);
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
  Adaptation adaptation_;
  int bits_;
  uint64_t low_ = 0;
  uint32_t range_ = 0xFFFFFFFFu;
  uint8_t cache_ = 0;
  bool started_ = false;
  size_t pending_ = 0;
  std::string out_;
};

}  // namespace

ContextModels uniform_models() { return ContextModels(static_cast<size_t>(context_count) * 256); }

// Calls decide(model, bit, context) for each binary decision of `bytes`, down each byte's bit tree in its
// context, from the models `start`, in the encoder's order.
template <typename Decide>
void for_each_decision(const std::string& bytes, const std::vector<uint8_t>& contexts, const ContextModels& start,
                       Adaptation adaptation, Decide decide) {
  std::vector<WorkingModel> models = working_models(start, adaptation);
  for (size_t i = 0; i < bytes.size(); ++i) {
    WorkingModel* tree = &models[static_cast<size_t>(contexts[i]) * 256];
    const uint8_t value = static_cast<uint8_t>(bytes[i]);
    unsigned node = 1;
    for (int b = 7; b >= 0; --b) {
      const bool bit = (value >> b) & 1;
      decide(tree[node], bit, contexts[i]);
      node = 2 * node + bit;
    }
  }
}

std::string arithmetic_encode(const std::string& bytes, const std::vector<uint8_t>& contexts,
                              const ContextModels& start, Adaptation adaptation) {
  Encoder encoder(adaptation);
  for_each_decision(bytes, contexts, start, adaptation,
                    [&](WorkingModel& model, bool bit, uint8_t) { encoder.bit(model, bit); });
  return encoder.finish();
}

std::vector<double> arithmetic_cost_by_context(const std::string& bytes, const std::vector<uint8_t>& contexts,
                                               const ContextModels& start, Adaptation adaptation) {
  std::vector<double> bits(static_cast<size_t>(context_count), 0.0);
  const double one = static_cast<double>(1u << probability_bits(adaptation));
  for_each_decision(bytes, contexts, start, adaptation, [&](WorkingModel& model, bool bit, uint8_t context) {
    const double p_zero = probability(model, adaptation) / one;
    bits[context] -= std::log2(bit ? 1.0 - p_zero : p_zero);
    adapt(model, bit, adaptation);
  });
  return bits;
}

ArithmeticDecoder::ArithmeticDecoder(const char* coded, size_t size, const ContextModels& start,
                                     Adaptation adaptation)
    : coded_(coded), size_(size), adaptation_(adaptation), models_(working_models(start, adaptation)) {
  for (int i = 0; i < 4; ++i) code_ = (code_ << 8) | input();
}

uint8_t ArithmeticDecoder::input() { return position_ < size_ ? static_cast<uint8_t>(coded_[position_++]) : 0; }

bool ArithmeticDecoder::bit(WorkingModel& m) {
  const uint32_t bound = (range_ >> probability_bits(adaptation_)) * probability(m, adaptation_);
  bool b;
  if (code_ < bound) { range_ = bound; b = false; }
  else { code_ -= bound; range_ -= bound; b = true; }
  adapt(m, b, adaptation_);
  while (range_ < top) { range_ <<= 8; code_ = (code_ << 8) | input(); }
  return b;
}

uint8_t ArithmeticDecoder::next(int context) {
  WorkingModel* tree = &models_[static_cast<size_t>(context) * 256];
  unsigned node = 1;
  for (int b = 0; b < 8; ++b) node = 2 * node + (bit(tree[node]) ? 1 : 0);
  return static_cast<uint8_t>(node - 256);
}

}  // namespace cadnurbs::cnb
