#pragma once
// The WorldInfo info strings cadnurbs writes and reads back:
//   "generator cadnurbs"
//   "unit mm"                       (unknown names carry their size: "unit furlong 201168")
//   "controlPoint homogeneous"      or "controlPoint euclidean"
//   "name <DEF> <original name>"    one per DEF that is not the node's or shape's own name (names that
//                                   had to be sanitised or made unique; nothing after the DEF: no name).
//                                   DEFs of the form "_<digits>" are the writer's own (shared nodes) and
//                                   name nothing, unless such a line says otherwise.
// Other strings are ignored, so files from other tools keep their notes.
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/scene.hpp"

namespace cadnurbs {

struct WorldInfoConventions {
  std::optional<LengthUnit> unit;
  std::optional<bool> homogeneous_control_points;
  std::map<std::string, std::string> names;  // DEF -> original name
};

// The info strings for a file in `unit`, with the given control point convention and renamings
// (DEF, original name).
std::vector<std::string> world_info_strings(const LengthUnit& unit, bool homogeneous,
                                            const std::vector<std::pair<std::string, std::string>>& renamed);

// What the strings say. Throws std::invalid_argument naming the string when a "unit" or "controlPoint"
// line cannot be understood (an unknown unit without a size, a convention other than the two).
WorldInfoConventions parse_world_info(const std::vector<std::string>& info);

}  // namespace cadnurbs
