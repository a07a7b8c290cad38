#include "formats/step/native/step_colours.hpp"

#include <optional>
#include <string_view>

namespace cadnurbs::step {

namespace {

std::optional<Colour> pre_defined(std::string_view name) {
  static constexpr std::pair<std::string_view, Colour> table[] = {
      {"red", {1, 0, 0}},     {"green", {0, 1, 0}},   {"blue", {0, 0, 1}},  {"yellow", {1, 1, 0}},
      {"magenta", {1, 0, 1}}, {"cyan", {0, 1, 1}},    {"black", {0, 0, 0}}, {"white", {1, 1, 1}}};
  for (const auto& [known, colour] : table)
    if (known == name) return colour;
  return std::nullopt;
}

class ColourReader {
 public:
  explicit ColourReader(const StepContext& context) : c_(context), m_(context.model), t_(context.types) {}

  // The surface fill colour among a styled item's styles.
  std::optional<Colour> styled(EntityId item) const {
    const part21::Value styles = m_.parameter(*record_of(item), first_of(item));
    for (std::size_t k = 0; k < styles.size(); ++k) {
      const EntityId assignment = styles.item(k).reference();
      if (!c_.is(assignment, t_.presentation_style_assignment)) continue;
      const part21::Value list = m_.parameter(m_.records(assignment)[0], 0);
      for (std::size_t s = 0; s < list.size(); ++s) {
        if (list.item(s).kind() != part21::ValueKind::reference) continue;
        if (auto colour = usage(list.item(s).reference())) return colour;
      }
    }
    return std::nullopt;
  }

  // The record holding (styles, item): a simple STYLED_ITEM or OVER_RIDING_STYLED_ITEM's own record,
  // after its name; in a complex instance (an annotation occurrence, say) STYLED_ITEM's partial record,
  // which holds just (styles, item), the name being REPRESENTATION_ITEM's.
  const part21::Record* record_of(EntityId item) const {
    if (m_.is_complex(item)) return m_.record(item, t_.styled_item);
    if (c_.is(item, t_.over_riding_styled_item)) return m_.record(item, t_.over_riding_styled_item);
    return m_.record(item, t_.styled_item);
  }
  std::size_t first_of(EntityId item) const { return m_.is_complex(item) ? 0 : 1; }

 private:
  std::optional<Colour> usage(EntityId entity) const {
    if (!c_.is(entity, t_.surface_style_usage)) return std::nullopt;
    const EntityId side = m_.parameter(m_.records(entity)[0], 1).reference();
    if (!c_.is(side, t_.surface_side_style)) return std::nullopt;
    const part21::Value elements = m_.parameter(m_.records(side)[0], 1);
    for (std::size_t k = 0; k < elements.size(); ++k) {
      const EntityId element = elements.item(k).reference();
      if (!c_.is(element, t_.surface_style_fill_area)) continue;
      const EntityId fill = m_.parameter(m_.records(element)[0], 0).reference();
      if (!c_.is(fill, t_.fill_area_style)) continue;
      const part21::Value fills = m_.parameter(m_.records(fill)[0], 1);
      for (std::size_t f = 0; f < fills.size(); ++f) {
        const EntityId colour_fill = fills.item(f).reference();
        if (!c_.is(colour_fill, t_.fill_area_style_colour)) continue;
        if (auto colour = colour_of(m_.parameter(m_.records(colour_fill)[0], 1).reference())) return colour;
      }
    }
    return std::nullopt;
  }

  std::optional<Colour> colour_of(EntityId colour) const {
    if (c_.is(colour, t_.colour_rgb)) {
      const auto& r = *m_.record(colour, t_.colour_rgb);
      return Colour{m_.parameter(r, 1).number(), m_.parameter(r, 2).number(), m_.parameter(r, 3).number()};
    }
    if (c_.is(colour, t_.draughting_pre_defined_colour))
      return pre_defined(m_.parameter(m_.records(colour)[0], 0).text());
    return std::nullopt;
  }

  const StepContext& c_;
  const part21::Model& m_;
  const StepTypes& t_;
};

bool styleable(const StepContext& context, EntityId entity) {
  const auto& t = context.types;
  for (TypeId type : {t.advanced_face, t.manifold_solid_brep, t.brep_with_voids, t.closed_shell, t.open_shell,
                      t.oriented_closed_shell, t.shell_based_surface_model})
    if (context.is(entity, type)) return true;
  return false;
}

}  // namespace

std::unordered_map<EntityId, Colour> read_colours(const StepContext& context) {
  std::unordered_map<EntityId, Colour> out;
  const ColourReader reader(context);
  // Plain styled items first, over-riding ones after, so theirs win.
  for (TypeId type : {context.types.styled_item, context.types.over_riding_styled_item}) {
    if (type == part21::none) continue;
    for (EntityId item : context.model.of_type(type)) {
      if (type == context.types.styled_item && context.is(item, context.types.over_riding_styled_item)) continue;
      reading(context, item, [&] {
        const part21::Record* record = reader.record_of(item);
        if (!record) return 0;  // a complex instance without STYLED_ITEM's record: nothing the reader styles
        const part21::Value target = context.model.parameter(*record, reader.first_of(item) + 1);
        // Only faces, solids and shells are looked up; styles of anything else (annotations, curves,
        // representations, mapped items) are never read.
        if (target.kind() != part21::ValueKind::reference || !styleable(context, target.reference())) return 0;
        if (auto colour = reader.styled(item)) out[target.reference()] = *colour;
        return 0;
      });
    }
  }
  return out;
}

}  // namespace cadnurbs::step
