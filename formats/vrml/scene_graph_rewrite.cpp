#include "formats/vrml/scene_graph_rewrite.hpp"

#include <functional>
#include <set>

#include "formats/vrml/classic_encoding.hpp"
#include "formats/vrml/dialect_translation.hpp"
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

}  // namespace

RewrittenSceneGraph rewrite_scene_graph(const std::string& bytes, const std::string& name_for_errors,
                                        const VrmlWriteOptions& options) {
  NodeDocument document = parse_vrml_document(bytes, name_for_errors);
  RewrittenSceneGraph out;
  const VrmlDialect target = options.encoding == VrmlEncoding::vrml97 ? VrmlDialect::vrml97 : VrmlDialect::x3d;
  out.notes = translate_dialect(document, target);
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
