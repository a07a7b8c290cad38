#include "formats/vrml/share_repeated_nodes.hpp"

#include <map>
#include <unordered_map>

#include "formats/vrml/node_text.hpp"

namespace cadnurbs {

namespace {

// "DEF _12 " once and "USE _12" per repeat: below this many bytes a node is cheaper written again.
constexpr size_t min_shared_bytes = 24;

struct Summary {
  int id = 0;        // equal ids: equal text
  size_t bytes = 0;  // about the written size
};

class Sharer {
 public:
  explicit Sharer(IdentifierRegistry& ids) : ids_(ids) {}

  void run(NodeDocument& document) {
    for (auto& root : document.roots) summarise(root);
    for (auto& root : document.roots)
      if (root) visit_fields(*root);
  }

 private:
  static bool shareable(const Node& node) {
    return node.def_name.empty() || is_generated_identifier(node.def_name);
  }

  // Bottom up: equal subtrees get equal ids (hash-consing on the written text).
  const Summary& summarise(const NodePtr& node) {
    static const Summary null_summary{};
    if (!node) return null_summary;
    if (auto it = summaries_.find(node.get()); it != summaries_.end()) return it->second;
    std::string key = node->type + (node->def_name.empty() || is_generated_identifier(node->def_name) ? "" : "=" + node->def_name);
    size_t bytes = node->type.size() + 3;
    for (const auto& field : node->fields) {
      key += ' ' + field.name + ' ';
      if (const auto* sf = std::get_if<SFNode>(&field.value)) {
        const Summary& child = summarise(sf->node);
        key += '#' + std::to_string(child.id);
        bytes += child.bytes;
      } else if (const auto* mf = std::get_if<MFNode>(&field.value)) {
        key += '[' + children_key(*mf, &bytes) + ']';
      } else {
        append_value(key, field);
      }
    }
    bytes += key.size();
    const auto [it, inserted] = ids_of_text_.try_emplace(std::move(key), static_cast<int>(ids_of_text_.size()) + 1);
    return summaries_[node.get()] = Summary{it->second, bytes};
  }

  std::string children_key(const MFNode& children, size_t* bytes) {
    std::string key;
    for (const auto& child : children.nodes) {
      const Summary& s = summarise(child);
      key += '#' + std::to_string(s.id);
      *bytes += s.bytes;
    }
    return key;
  }

  static void append_value(std::string& out, const Field& field) {
    const FieldValue& v = field.value;
    if (const auto* b = std::get_if<bool>(&v)) out += *b ? "TRUE" : "FALSE";
    else if (const auto* s = std::get_if<std::string>(&v)) out += quoted_string(*s);
    else if (const auto* strings = std::get_if<MFString>(&v))
      for (const auto& s : strings->values) out += quoted_string(s);
    else append_numeric_value(out, v, field.precision);
  }

  // Top down, in writing order: the first occurrence stays, later ones become USEs.
  void visit(NodePtr& slot) {
    if (!slot) return;
    const Summary& s = summarise(slot);
    if (shareable(*slot) && s.bytes >= min_shared_bytes) {
      const auto [it, first] = first_of_.try_emplace(s.id, slot);
      if (!first && it->second != slot) {
        if (it->second->def_name.empty()) it->second->def_name = ids_.claim_generated();
        slot = it->second;
        return;
      }
    }
    if ((slot->type == "Transform" || slot->type == "Group") && share_children(*slot)) return;
    visit_fields(*slot);
  }

  void visit_fields(Node& node) {
    for (auto& field : node.fields) {
      if (auto* sf = std::get_if<SFNode>(&field.value)) visit(sf->node);
      if (auto* mf = std::get_if<MFNode>(&field.value))
        for (auto& child : mf->nodes) visit(child);
    }
  }

  static MFNode* children_of(Node& node) {
    for (auto& field : node.fields)
      if (field.name == "children") return std::get_if<MFNode>(&field.value);
    return nullptr;
  }

  // A Transform (or Group) whose children equal an earlier one's: both hold one shared Group of them.
  bool share_children(Node& grouping) {
    MFNode* children = children_of(grouping);
    // One child is shared by itself (visit), without a Group around it.
    if (!children || children->nodes.size() < 2) return false;
    size_t bytes = 0;
    const std::string key = children_key(*children, &bytes);
    if (bytes < min_shared_bytes) return false;
    const auto [it, first] = first_children_.try_emplace(key, &grouping);
    if (first) return false;
    NodePtr& group = group_of_[it->second];
    if (!group) {
      MFNode* earlier = children_of(*it->second);
      group = make_node("Group", ids_.claim_generated());
      group->set("children", std::move(*earlier));
      *earlier = MFNode{{group}};
    }
    *children = MFNode{{group}};
    return true;
  }

  IdentifierRegistry& ids_;
  std::unordered_map<const Node*, Summary> summaries_;
  std::unordered_map<std::string, int> ids_of_text_;
  std::unordered_map<int, NodePtr> first_of_;
  std::map<std::string, Node*> first_children_;
  std::unordered_map<const Node*, NodePtr> group_of_;  // the shared Group of a first Transform
};

}  // namespace

void share_repeated_nodes(NodeDocument& document, IdentifierRegistry& ids) { Sharer(ids).run(document); }

}  // namespace cadnurbs
