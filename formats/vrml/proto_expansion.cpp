#include "formats/vrml/proto_expansion.hpp"

#include <map>
#include <stdexcept>

namespace cadnurbs {

namespace {

// Values of a PROTO's fields inside one expansion of its body.
using Bindings = std::map<std::string, FieldValue>;

class ProtoExpander {
 public:
  ProtoExpander(const ExternProtoLoader& load_extern, size_t max_nodes)
      : load_extern_(load_extern), max_nodes_(max_nodes) {}

  ExpandedProtos expand(const NodeDocument& document) {
    Context top{{&document}, nullptr, {}, 0};
    for (const auto& root : document.roots) out_.roots.push_back(copy(root, top));
    return std::move(out_);
  }

 private:
  struct Context {
    std::vector<const NodeDocument*> scopes;  // outermost first
    const Bindings* bindings;                 // the enclosing body's PROTO fields; null outside bodies
    std::map<const Node*, NodePtr> copies;    // this DEF scope's copies, so that USE stays shared
    int depth;                                // PROTO bodies entered
  };

  // The innermost declaration of `name` in scope.
  static const ProtoDeclaration* find(const Context& context, const std::string& name) {
    for (auto scope = context.scopes.rbegin(); scope != context.scopes.rend(); ++scope)
      for (auto it = (*scope)->protos.rbegin(); it != (*scope)->protos.rend(); ++it)
        if (it->name == name) return &*it;
    return nullptr;
  }

  FieldValue copy_value(const FieldValue& value, Context& context) {
    if (const auto* sf = std::get_if<SFNode>(&value)) return SFNode{copy(sf->node, context)};
    if (const auto* mf = std::get_if<MFNode>(&value)) {
      MFNode out;
      for (const auto& node : mf->nodes) out.nodes.push_back(copy(node, context));
      return out;
    }
    return value;
  }

  // The node's own fields copied, and its IS fields given the enclosing body's values.
  NodePtr copy_fields(const Node& source, Context& context) {
    if (++nodes_ > max_nodes_)
      throw std::length_error("PROTO instances expand to more than " + std::to_string(max_nodes_) + " nodes");
    auto node = std::make_shared<Node>();
    node->type = source.type;
    node->def_name = source.def_name;
    node->line = source.line;
    node->proto_instance = source.proto_instance;
    node->declarations = source.declarations;
    for (const auto& field : source.fields)
      node->fields.push_back(Field{field.name, copy_value(field.value, context), field.precision, field.line});
    for (const auto& is : source.is_connections) {
      if (!context.bindings) continue;
      auto bound = context.bindings->find(is.proto_field);
      if (bound != context.bindings->end()) node->set(is.node_field, bound->second);  // an event binds no value
    }
    return node;
  }

  NodePtr copy(const NodePtr& source, Context& context) {
    if (!source) return nullptr;
    if (auto done = context.copies.find(source.get()); done != context.copies.end()) return done->second;
    NodePtr node = copy_fields(*source, context);
    if (node->proto_instance) node = instantiate(node, context);
    context.copies[source.get()] = node;
    return node;
  }

  // `instance` (fields already resolved in the caller's context) as a copy of its PROTO's body, or
  // itself when the PROTO cannot be expanded.
  NodePtr instantiate(const NodePtr& instance, const Context& context) {
    if (context.depth >= kMaxProtoDepth) return instance;
    const ProtoDeclaration* proto = find(context, instance->type);
    if (!proto) return instance;
    std::vector<const NodeDocument*> scopes = context.scopes;
    if (proto->external) {
      const LoadedProto loaded = load_extern_ ? load_extern_(*proto) : LoadedProto{};
      if (!loaded.proto || loaded.proto->external || !loaded.proto->body) return instance;
      scopes = {loaded.file};
      proto = loaded.proto;
    }
    if (!proto->body) return instance;
    Bindings bindings;
    Context defaults{scopes, nullptr, {}, context.depth + 1};
    for (const auto& declaration : proto->interface) {
      if (const Field* given = instance->find(declaration.name))
        bindings[declaration.name] = given->value;
      else if (declaration.default_value)
        bindings[declaration.name] = copy_value(*declaration.default_value, defaults);
    }
    scopes.push_back(proto->body.get());
    Context body{scopes, &bindings, {}, context.depth + 1};
    const NodeDocument& nodes = *proto->body;
    ++out_.expanded;
    out_.body_routes += nodes.routes.size();
    if (nodes.roots.size() > 1) out_.body_extra_roots += nodes.roots.size() - 1;
    if (nodes.roots.empty() || !nodes.roots.front()) return nullptr;
    NodePtr first = copy(nodes.roots.front(), body);
    // The instance's DEF names what it became (a copy: a USE of the body's node elsewhere keeps its name).
    if (!instance->def_name.empty() && first) {
      first = std::make_shared<Node>(*first);
      first->def_name = instance->def_name;
    }
    return first;
  }

  const ExternProtoLoader& load_extern_;
  size_t max_nodes_;
  size_t nodes_ = 0;
  ExpandedProtos out_;
};

}  // namespace

ExpandedProtos expand_protos(const NodeDocument& document, const ExternProtoLoader& load_extern, size_t max_nodes) {
  return ProtoExpander(load_extern, max_nodes).expand(document);
}

}  // namespace cadnurbs
