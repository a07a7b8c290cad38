#include "formats/vrml/node_graph.hpp"

namespace cadnurbs {

const Field* Node::find(std::string_view name) const {
  for (const auto& field : fields)
    if (field.name == name) return &field;
  return nullptr;
}

void Node::set(std::string name, FieldValue value, NumberPrecision precision) {
  for (auto& field : fields)
    if (field.name == name) {
      field.value = std::move(value);
      field.precision = precision;
      return;
    }
  fields.push_back(Field{std::move(name), std::move(value), precision, 0});
}

NodePtr make_node(std::string type, std::string def_name) {
  auto node = std::make_shared<Node>();
  node->type = std::move(type);
  node->def_name = std::move(def_name);
  return node;
}

}  // namespace cadnurbs
