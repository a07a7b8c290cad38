// libFuzzer target over the Part 21 parser of the native STEP reader (formats/step/part21): every byte
// string goes to parse_part21, which must return a Model or throw FileError, in time and memory linear in
// the input; then every value of every entity is walked (lists and typed parameters without recursion),
// each read through the accessor of its kind, so that a slot pointing outside the tables is found too.
// Run by tests/fuzz/run_fuzz.sh (ctest: fuzz.part21).
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "formats/common/file_io.hpp"
#include "formats/step/part21/parse_part21.hpp"

using namespace cadnurbs::part21;

namespace {

// Reads every value reachable from `top`, each with the accessor its kind allows.
std::size_t walk(const Model& model, Value top) {
  std::size_t seen = 0;
  std::vector<Value> pending{top};
  while (!pending.empty()) {
    const Value value = pending.back();
    pending.pop_back();
    ++seen;
    switch (value.kind()) {
      case ValueKind::integer: seen += value.integer() == 0; break;
      case ValueKind::real: seen += value.number() == 0.0; break;
      case ValueKind::string:
      case ValueKind::binary: seen += value.text().size(); break;
      case ValueKind::enumeration:
        seen += value.text().size();
        if (value.text() == "T" || value.text() == "F") seen += value.boolean();
        break;
      case ValueKind::reference: seen += model.number(value.reference()) == value.reference_number(); break;
      case ValueKind::list:
        for (std::size_t k = 0; k < value.size(); ++k) pending.push_back(value.item(k));
        break;
      case ValueKind::typed:
        seen += model.type_name(value.type()).size();
        pending.push_back(value.inner());
        break;
      case ValueKind::unset:
      case ValueKind::derived: break;
    }
  }
  return seen;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    const Model model = parse_part21(bytes, "fuzz.step");
    std::size_t seen = model.file_schemas().size();
    for (EntityId id = 0; id < model.size(); ++id) {
      if (model.find(model.number(id)) != id) __builtin_trap();
      seen += model.entity_text(id).size();
      for (const Record& record : model.records(id)) {
        if (!model.is(id, record.type)) __builtin_trap();
        for (std::size_t k = 0; k < record.count; ++k) seen += walk(model, model.parameter(record, k));
      }
    }
    for (TypeId type = 0; type < model.type_count(); ++type)
      for (const EntityId id : model.of_type(type))
        if (!model.is(id, type)) __builtin_trap();
    if (seen == 1) return 0;  // keeps the walk from being optimised away
  } catch (const cadnurbs::FileError&) {
  }
  return 0;
}
