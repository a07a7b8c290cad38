// The coder prior of .cnb format version 4 (formats/cnb/cnb_coder_prior.hpp), made and measured.
//
//   cnb_coder_prior table FILE.cnb...   prints cnb_coder_prior_table.inc: for each context and bit-tree
//                                       model, the level nearest the share of 0 bits it saw in the files'
//                                       payloads ((zeros + ½) / (bits + 1)); "." where it saw fewer than 2
//   cnb_coder_prior cost FILE.cnb...    for each file, its payload arithmetic-coded with every model at ½
//                                       (coder 2), from the prior (coder 3, version 4 on) and from the
//                                       prior with models of two rates (coder 4, version 7 on), in bytes
//   cnb_coder_prior contexts FILE.cnb...  where coder 4 spends the files' payloads: for each context, its
//                                       bytes before coding and its bits after, summed over the files
//
// bench/cnb_coder_prior.sh runs `table` on the training files. The payloads are read back with their
// contexts by read_cnb_payload, so a file of any version trains alike.
#include <cstdio>
#include <string>
#include <vector>

#include "formats/cnb/adaptive_arithmetic_coder.hpp"
#include "formats/cnb/cnb_coder_prior.hpp"
#include "formats/cnb/cnb_reader.hpp"
#include "formats/common/file_io.hpp"

using namespace cadnurbs;

namespace {

CnbPayload payload_of(const char* path) { return read_cnb_payload(read_file(path), path); }

int table(int count, char** paths) {
  const size_t models = static_cast<size_t>(cnb::context_count) * 256;
  std::vector<double> zeros(models, 0), bits(models, 0);
  for (int i = 0; i < count; ++i) {
    const CnbPayload p = payload_of(paths[i]);
    for (size_t k = 0; k < p.bytes.size(); ++k) {
      const uint8_t value = static_cast<uint8_t>(p.bytes[k]);
      unsigned node = 1;
      for (int b = 7; b >= 0; --b) {
        const bool bit = (value >> b) & 1;
        const size_t m = static_cast<size_t>(p.contexts[k]) * 256 + node;
        bits[m] += 1;
        if (!bit) zeros[m] += 1;
        node = 2 * node + bit;
      }
    }
  }
  std::printf("// Made by bench/cnb_coder_prior.sh from %d files; part of .cnb format version 4\n", count);
  std::printf("// (cnb_coder_prior.hpp): do not edit. One string per context (2 per field, then the 8 float64\n");
  std::printf("// bytes), one character per bit-tree model (node 1 to 255): a level 0-9a-f, or . for a model the\n");
  std::printf("// training met fewer than 2 times.\n");
  std::printf("constexpr int coder_prior_contexts = %d;\n", cnb::context_count);
  std::printf("constexpr const char* coder_prior_levels[coder_prior_contexts] = {\n");
  for (int c = 0; c < cnb::context_count; ++c) {
    std::string levels;
    for (int node = 1; node < 256; ++node) {
      const size_t m = static_cast<size_t>(c) * 256 + node;
      levels += bits[m] < 2 ? '.' : "0123456789abcdef"[cnb::prior_level((zeros[m] + 0.5) / (bits[m] + 1))];
    }
    std::printf("    \"%s\",\n", levels.c_str());
  }
  std::printf("};\n");
  return 0;
}

int cost(int count, char** paths) {
  size_t uniform_total = 0, prior_total = 0, two_rates_total = 0;
  for (int i = 0; i < count; ++i) {
    const CnbPayload p = payload_of(paths[i]);
    const auto coded = [&](const cnb::ContextModels& start, cnb::Adaptation adaptation) {
      return cnb::arithmetic_encode(p.bytes, p.contexts, start, adaptation).size();
    };
    const size_t uniform = coded(cnb::uniform_models(), cnb::Adaptation::one_rate);
    const size_t prior = coded(cnb::coder_prior_models(p.version), cnb::Adaptation::one_rate);
    const size_t two_rates = coded(cnb::coder_prior_models(p.version), cnb::Adaptation::two_rates);
    std::printf("%s\t%zu\t%zu\t%zu\t%zu\n", paths[i], p.bytes.size(), uniform, prior, two_rates);
    uniform_total += uniform;
    prior_total += prior;
    two_rates_total += two_rates;
  }
  std::printf("all\t\t%zu\t%zu\t%zu\n", uniform_total, prior_total, two_rates_total);
  return 0;
}

// A context's name: its field and whether a varint's first byte, a float64's byte, or one of the contexts
// of version 4 and 8 on (cnb_stream.hpp).
std::string context_name(int c) {
  static const char* fields[cnb::field_count] = {"structure", "count", "text", "knot", "weight",
                                                 "point", "trim", "index", "raw", "symbol",
                                                 "mesh_point", "mesh_rank", "mesh_axes", "mesh_member"};
  if (c < 2 * cnb::field_count) return std::string(fields[c / 2]) + (c % 2 ? " (more)" : "");
  c -= 2 * cnb::field_count;
  if (c < 8) return "float64 byte " + std::to_string(c);
  c -= 8;
  if (c < cnb::mesh_symbol_count) return "symbol after " + std::to_string(c);
  c -= cnb::mesh_symbol_count;
  if (c < 4) return std::string(c < 2 ? "mesh_rank" : "mesh_point") + " axis " + std::to_string(c % 2 + 1);
  c -= 4;
  if (c < cnb::vertex_predictor_contexts) return "predictor after " + std::to_string(c);
  c -= cnb::vertex_predictor_contexts;
  if (c < cnb::gate_symbol_contexts) return "symbol after 0 at shape " + std::to_string(c);
  return "border place";
}

int contexts(int count, char** paths) {
  std::vector<double> bits(cnb::context_count, 0.0), bytes(cnb::context_count, 0.0);
  for (int i = 0; i < count; ++i) {
    const CnbPayload p = payload_of(paths[i]);
    const std::vector<double> cost = cnb::arithmetic_cost_by_context(p.bytes, p.contexts, cnb::coder_prior_models(p.version),
                                                                     cnb::Adaptation::two_rates);
    for (int c = 0; c < cnb::context_count; ++c) bits[c] += cost[c];
    for (uint8_t c : p.contexts) bytes[c] += 1;
  }
  double total = 0;
  for (double b : bits) total += b;
  std::printf("context\tname\tbytes\tcoded bytes\tshare\n");
  for (int c = 0; c < cnb::context_count; ++c)
    if (bytes[c] > 0)
      std::printf("%d\t%s\t%.0f\t%.0f\t%.1f%%\n", c, context_name(c).c_str(), bytes[c], bits[c] / 8,
                  100 * bits[c] / total);
  std::printf("all\t\t\t%.0f\n", total / 8);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  try {
    if (mode == "table" && argc > 2) return table(argc - 2, argv + 2);
    if (mode == "cost" && argc > 2) return cost(argc - 2, argv + 2);
    if (mode == "contexts" && argc > 2) return contexts(argc - 2, argv + 2);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cnb_coder_prior: %s\n", e.what());
    return 1;
  }
  std::fprintf(stderr, "usage: cnb_coder_prior table|cost|contexts FILE.cnb...\n");
  return 2;
}
