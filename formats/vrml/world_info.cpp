#include "formats/vrml/world_info.hpp"

#include <charconv>
#include <sstream>
#include <stdexcept>

#include "core/chars_to_double.hpp"
#include "core/length_unit.hpp"
#include "core/number_format.hpp"

namespace cadnurbs {

namespace {

std::optional<double> known_size(const std::string& name) {
  if (const auto unit = length_unit_named(name)) return unit->millimetres;
  return std::nullopt;
}

}  // namespace

std::vector<std::string> world_info_strings(const LengthUnit& unit, bool homogeneous,
                                            const std::vector<std::pair<std::string, std::string>>& renamed) {
  std::vector<std::string> out = {"generator cadnurbs"};
  std::string unit_line = "unit " + unit.name;
  if (known_size(unit.name) != unit.millimetres) unit_line += " " + format_number(unit.millimetres, {});
  out.push_back(unit_line);
  out.push_back(homogeneous ? "controlPoint homogeneous" : "controlPoint euclidean");
  for (const auto& [def, original] : renamed) out.push_back("name " + def + (original.empty() ? "" : " " + original));
  return out;
}

WorldInfoConventions parse_world_info(const std::vector<std::string>& info) {
  WorldInfoConventions c;
  for (const auto& line : info) {
    std::istringstream in(line);
    std::string key;
    in >> key;
    if (key == "unit") {
      std::string name, size;
      in >> name >> size;
      if (name.empty()) throw std::invalid_argument("info \"" + line + "\" names no unit");
      double millimetres = 0.0;
      if (!size.empty()) {
        const auto r = chars_to_double(size.data(), size.data() + size.size(), millimetres);
        if (r.ec != std::errc() || r.ptr != size.data() + size.size() || !(millimetres > 0.0))
          throw std::invalid_argument("info \"" + line + "\": unit size is not a positive number");
      } else if (auto known = known_size(name)) {
        millimetres = *known;
      } else {
        throw std::invalid_argument("info \"" + line + "\": unknown unit without a size in millimetres");
      }
      c.unit = LengthUnit{name, millimetres};
    } else if (key == "controlPoint") {
      std::string convention;
      in >> convention;
      if (convention == "homogeneous") c.homogeneous_control_points = true;
      else if (convention == "euclidean") c.homogeneous_control_points = false;
      else throw std::invalid_argument("info \"" + line + "\": control points are either homogeneous or euclidean");
    } else if (key == "name") {
      std::string def;
      in >> def;
      // Everything after "name <DEF> " is the original name, spaces included.
      const size_t start = line.find(def, 4) + def.size();
      c.names[def] = start < line.size() ? line.substr(start + 1) : std::string();
    }
  }
  return c;
}

}  // namespace cadnurbs
