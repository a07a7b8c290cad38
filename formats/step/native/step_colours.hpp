#pragma once
// Surface colours of a STEP file's presentation (ISO 10303-46 as AP214/AP242 use it): STYLED_ITEM ->
// PRESENTATION_STYLE_ASSIGNMENT -> SURFACE_STYLE_USAGE -> SURFACE_SIDE_STYLE -> SURFACE_STYLE_FILL_AREA
// -> FILL_AREA_STYLE -> FILL_AREA_STYLE_COLOUR -> COLOUR_RGB or DRAUGHTING_PRE_DEFINED_COLOUR.
#include <unordered_map>

#include "core/scene.hpp"
#include "formats/step/native/step_context.hpp"

namespace cadnurbs::step {

// Takes the file. Returns the surface colour of every styled face, solid or shell (items of anything else,
// such as annotation occurrences styled by complex STYLED_ITEM instances, are skipped), an
// OVER_RIDING_STYLED_ITEM's colour over a plain one. Styles without a surface fill colour (curve styles,
// invisibility) give none; a pre-defined colour outside ISO 10303-46's eight names gives none.
std::unordered_map<EntityId, Colour> read_colours(const StepContext& context);

}  // namespace cadnurbs::step
