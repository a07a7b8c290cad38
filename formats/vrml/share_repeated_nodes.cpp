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
    for (auto& root : document.roots) shape(root);
    for (auto& root : document.roots) summarise(root);
    for (auto& root : document.roots)
      if (root) visit_fields(*root);
  }

 private:
  // The type, and the DEF name when it is the scene's (generated names do not make nodes differ).
  static std::string name_key(const Node& node) {
    return node.type + (shareable(node) ? "" : "=" + node.def_name);
  }

  static bool shareable(const Node& node) {
    return node.def_name.empty() || is_generated_identifier(node.def_name);
  }

  // Bottom up: equal subtrees get equal ids (hash-consing on the written text). A node whose shape no
  // other node has cannot equal any, and gets an id of its own without its numbers being formatted:
  // a large mesh is then formatted once, by the writer, instead of twice.
  const Summary& summarise(const NodePtr& node) {
    static const Summary null_summary{};
    if (!node) return null_summary;
    if (auto it = summaries_.find(node.get()); it != summaries_.end()) return it->second;
    const bool alone = shape_counts_.at(shape(node)) == 1;
    std::string key = name_key(*node);
    size_t bytes = node->type.size() + 3;
    for (const auto& field : node->fields) {
      key += ' ' + field.name + ' ';
      if (const auto* sf = std::get_if<SFNode>(&field.value)) {
        const Summary& child = summarise(sf->node);
        key += '#' + std::to_string(child.id);
        bytes += child.bytes;
      } else if (const auto* mf = std::get_if<MFNode>(&field.value)) {
        key += '[' + children_key(*mf, &bytes) + ']';
      } else if (!alone) {
        append_value(key, field);
      }
    }
    bytes += key.size();
    if (alone) return summaries_[node.get()] = Summary{-static_cast<int>(summaries_.size()) - 1, bytes};
    const auto [it, inserted] = ids_of_text_.try_emplace(std::move(key), static_cast<int>(ids_of_text_.size()) + 1);
    return summaries_[node.get()] = Summary{it->second, bytes};
  }

  // What equal text needs and is cheap to tell: type, name, field names, the shapes of the children, the
  // value of single fields and the length of arrays. Equal text implies equal shape. Counted per node.
  int shape(const NodePtr& node) {
    if (!node) return 0;
    if (auto it = shapes_.find(node.get()); it != shapes_.end()) return it->second;
    std::string key = name_key(*node);
    for (const auto& field : node->fields) {
      key += ' ' + field.name + ' ';
      if (const auto* sf = std::get_if<SFNode>(&field.value)) {
        key += '#' + std::to_string(shape(sf->node));
      } else if (const auto* mf = std::get_if<MFNode>(&field.value)) {
        for (const auto& child : mf->nodes) key += '#' + std::to_string(shape(child));
      } else if (const size_t n = array_length(field.value); n > 0) {
        key += '(' + std::to_string(n) + ')';
      } else {
        append_value(key, field);
      }
    }
    const auto [it, inserted] = shape_ids_.try_emplace(std::move(key), static_cast<int>(shape_ids_.size()) + 1);
    ++shape_counts_[it->second];
    return shapes_[node.get()] = it->second;
  }

  // The number of values of a numeric array field (0 for anything else, and for an empty array).
  static size_t array_length(const FieldValue& v) {
    if (const auto* a = std::get_if<MFFloat>(&v)) return a->values.size();
    if (const auto* a = std::get_if<MFInt32>(&v)) return a->values.size();
    if (const auto* a = std::get_if<MFVec2f>(&v)) return a->values.size();
    if (const auto* a = std::get_if<MFVec3f>(&v)) return a->values.size();
    return 0;
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
  std::unordered_map<const Node*, int> shapes_;
  std::unordered_map<std::string, int> shape_ids_;
  std::unordered_map<int, int> shape_counts_;  // nodes per shape
  std::unordered_map<int, NodePtr> first_of_;
  std::map<std::string, Node*> first_children_;
  std::unordered_map<const Node*, NodePtr> group_of_;  // the shared Group of a first Transform
};

}  // namespace

void share_repeated_nodes(NodeDocument& document, IdentifierRegistry& ids) { Sharer(ids).run(document); }

}  // namespace cadnurbs
