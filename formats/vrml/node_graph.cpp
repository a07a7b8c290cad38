#include "formats/vrml/node_graph.hpp"

#include <set>

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

void for_each_node(const NodeDocument& document, const std::function<void(const Node&)>& visit) {
  std::set<const Node*> seen;
  std::function<void(const NodePtr&)> walk;
  auto walk_value = [&](const FieldValue& value) {
    if (const auto* sf = std::get_if<SFNode>(&value)) walk(sf->node);
    if (const auto* mf = std::get_if<MFNode>(&value))
      for (const auto& child : mf->nodes) walk(child);
  };
  walk = [&](const NodePtr& node) {
    if (!node || !seen.insert(node.get()).second) return;
    visit(*node);
    for (const auto& field : node->fields) walk_value(field.value);
  };
  std::function<void(const NodeDocument&)> walk_document = [&](const NodeDocument& d) {
    for (const auto& proto : d.protos) {
      for (const auto& declaration : proto.interface)
        if (declaration.default_value) walk_value(*declaration.default_value);
      if (proto.body) walk_document(*proto.body);
    }
    for (const auto& root : d.roots) walk(root);
  };
  walk_document(document);
}

void for_each_scope_node(NodeDocument& document, const std::function<void(Node&)>& visit) {
  std::set<const Node*> seen;
  std::function<void(const NodePtr&)> walk = [&](const NodePtr& node) {
    if (!node || !seen.insert(node.get()).second) return;
    visit(*node);
    for (const auto& field : node->fields) {
      if (const auto* sf = std::get_if<SFNode>(&field.value)) walk(sf->node);
      if (const auto* mf = std::get_if<MFNode>(&field.value))
        for (const auto& child : mf->nodes) walk(child);
    }
  };
  for (const auto& root : document.roots) walk(root);
}

std::string access_keyword(const std::string& access, VrmlDialect dialect) {
  static const char* const names[4][2] = {{"field", "initializeOnly"},
                                          {"exposedField", "inputOutput"},
                                          {"eventIn", "inputOnly"},
                                          {"eventOut", "outputOnly"}};
  for (const auto& pair : names)
    if (access == pair[0] || access == pair[1]) return pair[dialect == VrmlDialect::vrml97 ? 0 : 1];
  return access;
}

NodePtr make_node(std::string type, std::string def_name) {
  auto node = std::make_shared<Node>();
  node->type = std::move(type);
  node->def_name = std::move(def_name);
  return node;
}

}  // namespace cadnurbs
