#include "formats/step/native/step_units.hpp"

#include <cctype>
#include <cmath>
#include <optional>
#include <string_view>
#include <utility>

namespace cadnurbs::step {

namespace {

// SI prefixes (ISO 10303-41 si_prefix) as powers of ten.
std::optional<int> prefix_exponent(std::string_view prefix) {
  static constexpr std::pair<std::string_view, int> table[] = {
      {"EXA", 18},  {"PETA", 15},  {"TERA", 12},  {"GIGA", 9},   {"MEGA", 6},   {"KILO", 3},
      {"HECTO", 2}, {"DECA", 1},   {"DECI", -1},  {"CENTI", -2}, {"MILLI", -3}, {"MICRO", -6},
      {"NANO", -9}, {"PICO", -12}, {"FEMTO", -15}, {"ATTO", -18}};
  for (const auto& [name, exponent] : table)
    if (name == prefix) return exponent;
  return std::nullopt;
}

// The size of a unit: metres for lengths, radians for angles; `name` gets its name.
double unit_size(const StepContext& context, EntityId unit, std::string& name, int depth) {
  const part21::Model& m = context.model;
  const auto& t = context.types;
  if (depth > 4) context.refuse(unit, "unit conversions nested too deep");
  if (context.is(unit, t.si_unit)) {
    const auto& r = *m.record(unit, t.si_unit);
    // SI_UNIT(prefix, name) as a partial record; a simple SI_UNIT has (dimensions, prefix, name).
    const std::size_t first = r.count == 3 ? 1 : 0;
    const part21::Value prefix = m.parameter(r, first), base = m.parameter(r, first + 1);
    double scale = 1.0;
    std::string prefix_name;
    if (prefix.kind() == part21::ValueKind::enumeration) {
      const auto exponent = prefix_exponent(prefix.text());
      if (!exponent) context.refuse(unit, "an unknown SI prefix ." + std::string(prefix.text()) + ".");
      scale = std::pow(10.0, *exponent);
      prefix_name = prefix.text();
    }
    std::string base_name(base.text());
    name.clear();
    for (char c : prefix_name + base_name) name += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return scale;
  }
  if (context.is(unit, t.conversion_based_unit)) {
    const auto& r = *m.record(unit, t.conversion_based_unit);
    name = std::string(m.parameter(r, 0).text());
    const EntityId measure = m.parameter(r, 1).reference();
    const auto records = m.records(measure);
    // ..._MEASURE_WITH_UNIT(value_component, unit_component), simple or the first record holding two.
    for (const auto& mr : records) {
      if (mr.count < 2) continue;
      part21::Value value = m.parameter(mr, 0);
      if (value.kind() == part21::ValueKind::typed) value = value.inner();
      const double factor = value.number();
      if (!(factor > 0) || !std::isfinite(factor)) context.refuse(measure, "a conversion factor that is not positive");
      std::string base_name;
      return factor * unit_size(context, m.parameter(mr, 1).reference(), base_name, depth + 1);
    }
    context.refuse(measure, "a conversion without a measure");
  }
  context.refuse(unit, "a unit that is neither an SI unit nor conversion-based");
}

}  // namespace

StepUnits read_units(const StepContext& context, EntityId representation_context) {
  StepUnits out;
  const part21::Model& m = context.model;
  const auto& t = context.types;
  if (!context.is(representation_context, t.global_unit_assigned_context)) return out;
  return reading(context, representation_context, [&] {
    const auto& r = *m.record(representation_context, t.global_unit_assigned_context);
    const part21::Value units = m.parameter(r, 0);
    for (std::size_t k = 0; k < units.size(); ++k) {
      const EntityId unit = units.item(k).reference();
      std::string name;
      if (context.is(unit, t.length_unit)) {
        out.millimetres = 1000.0 * unit_size(context, unit, name, 0);
        out.length_name = name;
      } else if (context.is(unit, t.plane_angle_unit)) {
        out.radians = unit_size(context, unit, name, 0);
      }
    }
    return out;
  });
}

}  // namespace cadnurbs::step
