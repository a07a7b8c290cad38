#include "formats/vrml/animation_at_rest.hpp"

#include <map>
#include <set>

namespace cadnurbs {

namespace {

// "set_point" and "point" name the same exposed field.
std::string field_of_event(const std::string& event) {
  if (event.starts_with("set_")) return event.substr(4);
  return event;
}

bool loops_from_load(const Node& time_sensor) {
  const bool* loop = time_sensor.get<bool>("loop");
  const bool* enabled = time_sensor.get<bool>("enabled");
  return time_sensor.type == "TimeSensor" && loop && *loop && (!enabled || *enabled);
}

}  // namespace

std::vector<std::string> apply_animation_at_rest(NodeDocument& document) {
  // Every DEF'd node of the document's scope, by name (the last DEF of a name wins, as it does for the
  // ROUTEs after it).
  std::map<std::string, Node*> defs;
  for_each_scope_node(document, [&](Node& node) {
    if (!node.def_name.empty()) defs[node.def_name] = &node;
  });
  auto named = [&](const std::string& name) -> Node* {
    const auto it = defs.find(name);
    return it == defs.end() ? nullptr : it->second;
  };
  // Interpolators a looping TimeSensor drives.
  std::set<const Node*> running;
  for (const auto& route : document.routes) {
    const Node* from = named(route.from_node);
    const Node* to = named(route.to_node);
    if (from && to && loops_from_load(*from) && route.from_field == "fraction_changed" &&
        field_of_event(route.to_field) == "fraction")
      running.insert(to);
  }
  std::map<std::string, size_t> counts;
  std::vector<std::string> order;
  for (const auto& route : document.routes) {
    const Node* interpolator = named(route.from_node);
    Node* target = named(route.to_node);
    if (!interpolator || !target || interpolator->type != "CoordinateInterpolator" || !running.count(interpolator) ||
        route.from_field != "value_changed")
      continue;
    const std::string field = field_of_event(route.to_field);
    const auto* keys = interpolator->get<MFFloat>("key");
    const auto* values = interpolator->get<MFVec3f>("keyValue");
    const auto* current = target->get<MFVec3f>(field);
    if (!keys || !values || keys->values.empty() || !current || values->values.size() % keys->values.size() != 0)
      continue;
    const size_t per_key = values->values.size() / keys->values.size();
    if (per_key != current->values.size()) continue;
    const std::vector<Eigen::Vector3d> first(values->values.begin(), values->values.begin() + static_cast<long>(per_key));
    for (auto& f : target->fields)
      if (f.name == field) f.value = MFVec3f{first};
    const std::string kind = "CoordinateInterpolator routed to " + target->type + "." + field;
    if (counts[kind]++ == 0) order.push_back(kind);
  }
  std::vector<std::string> notes;
  for (const auto& kind : order)
    notes.push_back(std::to_string(counts[kind]) + " " + kind + ": taken at the first key of its looping animation (fraction 0)");
  return notes;
}

}  // namespace cadnurbs
