#include "formats/vrml/scene_graph_rewrite.hpp"

#include <functional>
#include <map>
#include <set>

#include "formats/vrml/classic_encoding.hpp"
#include "formats/vrml/dialect_translation.hpp"
#include "formats/vrml/vrml_identifier.hpp"
#include "formats/vrml/vrml_reader.hpp"
#include "formats/vrml/xml_encoding.hpp"

namespace cadnurbs {

namespace {

// Nodes, kinds, ROUTEs and PROTO declarations, PROTO bodies included.
void count(const NodeDocument& document, RewrittenSceneGraph& out) {
  std::set<std::string> kinds;
  for_each_node(document, [&](const Node& node) {
    ++out.nodes;
    kinds.insert(node.type);
  });
  out.kinds = kinds.size();
  std::function<void(const NodeDocument&)> statements = [&](const NodeDocument& d) {
    out.routes += d.routes.size();
    out.protos += d.protos.size();
    for (const auto& proto : d.protos)
      if (proto.body) statements(*proto.body);
  };
  statements(document);
}

// Renames the DEF names that are not identifiers in every encoding (XML allows any string; a file may
// hold spaces or control characters in one) with IdentifierRegistry, in the ROUTEs and IMPORT/EXPORT
// statements too, scope by scope. Returns how many were renamed.
size_t make_names_legal(NodeDocument& d) {
  size_t renamed = 0;
  for (auto& proto : d.protos)
    if (proto.body) renamed += make_names_legal(*proto.body);
  IdentifierRegistry registry;
  std::map<std::string, std::string> names;
  for_each_scope_node(d, [&](Node& node) {
    if (!node.def_name.empty() && sanitised_identifier(node.def_name) == node.def_name) registry.claim(node.def_name);
  });
  for_each_scope_node(d, [&](Node& node) {
    if (node.def_name.empty() || sanitised_identifier(node.def_name) == node.def_name) return;
    auto it = names.find(node.def_name);
    if (it == names.end()) {
      it = names.emplace(node.def_name, registry.claim(node.def_name)).first;
      ++renamed;
    }
    node.def_name = it->second;
  });
  if (names.empty()) return renamed;
  auto rename = [&](std::string& name) {
    const auto it = names.find(name);
    if (it != names.end()) name = it->second;
  };
  for (auto& route : d.routes) {
    rename(route.from_node);
    rename(route.to_node);
  }
  // IMPORT's inline DEF and EXPORT's local DEF are names of this file; the others name what the other
  // file exports and what this one calls it.
  for (auto& statement : d.imports_exports) {
    if (statement.import) rename(statement.inline_def);
    else rename(statement.name);
  }
  return renamed;
}

}  // namespace

RewrittenSceneGraph rewrite_scene_graph(const std::string& bytes, const std::string& name_for_errors,
                                        const VrmlWriteOptions& options) {
  NodeDocument document = parse_vrml_document(bytes, name_for_errors);
  RewrittenSceneGraph out;
  const VrmlDialect target = options.encoding == VrmlEncoding::vrml97 ? VrmlDialect::vrml97 : VrmlDialect::x3d;
  out.notes = translate_dialect(document, target);
  if (const size_t renamed = make_names_legal(document))
    out.notes.push_back(std::to_string(renamed) + " DEF names renamed: they were not identifiers");
  document.profile = "Full";
  count(document, out);
  if (options.encoding == VrmlEncoding::x3d_xml) {
    out.text = xml_encoding(document, options.pretty);
  } else {
    ClassicEncodingOptions classic;
    classic.self_contained = options.self_contained;
    classic.protos_url = options.protos_url;
    classic.pretty = options.pretty;
    out.text = classic_encoding(document, classic);
  }
  return out;
}

}  // namespace cadnurbs
