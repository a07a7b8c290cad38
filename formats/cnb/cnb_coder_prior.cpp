#include "formats/cnb/cnb_coder_prior.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string_view>

namespace cadnurbs::cnb {

namespace {
#include "formats/cnb/cnb_coder_prior_table.inc"

constexpr bool table_complete() {
  for (const char* levels : coder_prior_levels)
    if (std::string_view(levels).size() != 255) return false;
  return true;
}
static_assert(table_complete(), "each context of the prior lists its 255 bit-tree models");
static_assert(coder_prior_contexts <= context_count, "the prior has more contexts than the coder");

ContextModels make_prior() {
  ContextModels models = uniform_models();
  for (int c = 0; c < coder_prior_contexts; ++c)
    for (int node = 1; node < 256; ++node) {
      const char level = coder_prior_levels[c][node - 1];
      if (level == '.') continue;
      const int l = level <= '9' ? level - '0' : level - 'a' + 10;
      models[static_cast<size_t>(c) * 256 + node] = {prior_level_probability[l], prior_seen};
    }
  return models;
}
}  // namespace

const uint16_t prior_level_probability[prior_levels] = {64,   81,   146,  258,  447,  747,  1184, 1743,
                                                        2353, 2912, 3349, 3649, 3838, 3950, 4015, 4032};

int prior_level(double probability_of_zero) {
  const double p = std::clamp(probability_of_zero, 1e-6, 1 - 1e-6);
  const double odds = std::log(p / (1 - p));
  int best = 0;
  for (int l = 1; l < prior_levels; ++l) {
    const double q = prior_level_probability[l] / 4096.0, best_q = prior_level_probability[best] / 4096.0;
    if (std::abs(std::log(q / (1 - q)) - odds) < std::abs(std::log(best_q / (1 - best_q)) - odds)) best = l;
  }
  return best;
}

const ContextModels& coder_prior_models(uint8_t version) {
  static const ContextModels table = make_prior();
  static const ContextModels split = [] {
    ContextModels models = table;
    const auto copy = [&](int to, int from) {
      std::copy_n(table.begin() + static_cast<ptrdiff_t>(from) * 256, 256,
                  models.begin() + static_cast<ptrdiff_t>(to) * 256);
    };
    for (int shape = 0; shape < gate_symbol_contexts; ++shape) copy(gate_symbol_context(shape), symbol_context(0));
    copy(border_place_context(), first_context(Field::index));
    for (int axis = 0; axis < 3; ++axis) {
      copy(value_context(Field::mesh_rank, axis, false), value_context(Field::mesh_rank, axis, true));
      copy(value_context(Field::mesh_point, axis, true), value_context(Field::mesh_point, axis, false));
    }
    copy(axes_context(false), axes_context(true));
    // A predictor is below 4: the first six decisions of its byte are 0 (nodes 1, 2, 4, ..., 32).
    for (uint8_t previous = 0; previous < vertex_predictor_contexts; ++previous)
      for (int node = 1; node < 64; node *= 2)
        models[static_cast<size_t>(predictor_context(previous)) * 256 + static_cast<size_t>(node)] = {
            prior_level_probability[13], prior_seen};
    return models;
  }();
  return version >= 9 ? split : table;
}

}  // namespace cadnurbs::cnb
