#pragma once
// The coder prior of .cnb format version 4 (docs/cnb.md, "The arithmetic coder"): where the models of
// each context's bit tree start in coder 3, instead of at ½ as in coder 2. A part written at D = 1 mm is a payload of a few
// hundred bytes, and an adaptive model that starts at ½ spends much of it learning what every payload
// shares: that counts and residuals are small, which mesh symbols are common, which letters names use.
// The prior is what a model learnt from the payloads of parts not in the part library
// (bench/cnb_coder_prior.sh: 14 corpus STEP and IGES files, each at D = 1 and 0.01 mm), stored as one of 16
// levels per model; a trained model starts as if it had seen `prior_seen` bits, so it still learns the
// file fast. The writer keeps whichever coder codes smaller: the prior helps small files (the 90
// library parts' payloads at 1 mm: 76,466 → 73,838 bytes) and costs large meshes unlike the training
// a few bytes (a capping's STL mesh at 1 mm: 0.2%). The table (cnb_coder_prior_table.inc) is part
// of the format: changing it needs a new version.
#include <cstdint>

#include "formats/cnb/adaptive_arithmetic_coder.hpp"

namespace cadnurbs::cnb {

constexpr int prior_levels = 16;
constexpr uint8_t prior_seen = 2;

// The probability of a 0 (of 4096) at each level: 4096 / (1 + e^(-(L - 7.5)·0.6)), rounded and kept
// within the coder's [64, 4032]. Stored as integers so that every platform decodes alike.
extern const uint16_t prior_level_probability[prior_levels];

// The level whose probability is nearest to `probability_of_zero` in log-odds (for the tool that makes
// the table).
int prior_level(double probability_of_zero);

// The models of the prior for a file of format version `version`, context_count × 256: a trained model at
// its level's probability with prior_seen bits seen, any other at ½ with none. Contexts beyond the table
// start at ½, except from version 9 on: the context of a symbol after a new vertex at each shape of the
// border starts as the table's context of the symbol after a new vertex, the border place's as the
// index's, and each vertex value's by whether its prediction is listed as the one that version 8 coded it
// in (cnb_vertex_values.hpp). Those contexts split models the table trained (cnb_stream.hpp); starting them at ½ would make
// each learn again that a symbol is below 8 (on the DFN/QFN sample of cnb_gate_shape.hpp, 150 contexts so
// started cost 8,449 bytes of symbols where version 8 spent 6,561). And the vertex predictors' contexts
// (version 8's start at ½) start sure, at level 13, that the first six decisions of a predictor are 0,
// since a predictor is below 4: the same sample's predictors, 2,078 bytes from ½, cost 1,719 so.
const ContextModels& coder_prior_models(uint8_t version);

}  // namespace cadnurbs::cnb
