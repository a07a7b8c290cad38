#include "formats/vrml/classic_encoding.hpp"

#include <cctype>
#include <functional>
#include <stdexcept>

#include "formats/vrml/node_text.hpp"
#include "formats/vrml/nurbs_protos.hpp"

namespace cadnurbs {

namespace {

// The VRML97 NURBS nodes (VRML97 amendment 1): not built into VRML97 browsers, so declared by PROTO.
bool is_vrml97_nurbs_node(const std::string& type) {
  return type == "NurbsSurface" || type == "TrimmedSurface" || type == "Contour2D" || type == "NurbsCurve2D" ||
         type == "Polyline2D" || type == "NurbsCurve" || type == "NurbsGroup";
}

// Names of the PROTOs in `protos` that `proto` mentions in its body (a PROTO built on another one).
std::set<std::string> mentioned_protos(const ProtoDefinition& proto, const std::vector<ProtoDefinition>& protos) {
  std::set<std::string> out;
  const std::string& text = proto.text;
  auto is_word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (size_t i = 0; i < text.size();) {
    if (!is_word(text[i])) {
      ++i;
      continue;
    }
    size_t j = i;
    while (j < text.size() && is_word(text[j])) ++j;
    const std::string word = text.substr(i, j - i);
    if (word != proto.name)
      for (const auto& other : protos)
        if (other.name == word) out.insert(word);
    i = j;
  }
  return out;
}

std::string proto_declarations(const NodeDocument& document, const ClassicEncodingOptions& options) {
  const auto& protos = nurbs_protos();
  auto find_proto = [&](const std::string& name) -> const ProtoDefinition* {
    for (const auto& p : protos)
      if (p.name == name) return &p;
    return nullptr;
  };
  std::set<std::string> used;
  for_each_node(document, [&](const Node& node) {
    if (node.proto_instance || !is_vrml97_nurbs_node(node.type)) return;
    const ProtoDefinition* proto = find_proto(node.type);
    if (!proto)
      throw std::runtime_error("the NURBS PROTO library has no PROTO " + node.type +
                               (protos.empty() ? " (the library was missing when cadnurbs was built)" : ""));
    for (const auto& field : node.fields)
      if (!declares(*proto, field.name))
        throw std::runtime_error("PROTO " + node.type + " of the NURBS PROTO library declares no field " + field.name);
    used.insert(node.type);
  });
  std::string out;
  if (!options.self_contained) {
    for (const auto& proto : protos)
      if (used.count(proto.name)) out += externproto_declaration(proto, options.protos_url);
    return out;
  }
  // A pasted PROTO must come after the PROTOs its body uses: close over them, paste in library order
  // (the library defines them before use).
  for (bool grew = true; grew;) {
    grew = false;
    for (const auto& proto : protos)
      if (used.count(proto.name))
        for (const auto& name : mentioned_protos(proto, protos)) grew |= used.insert(name).second;
  }
  for (const auto& proto : protos)
    if (used.count(proto.name)) out += proto.text;
  return out;
}

class ClassicWriter {
 public:
  ClassicWriter(std::string& out, bool pretty, VrmlDialect dialect = VrmlDialect::x3d)
      : out_(out), pretty_(pretty), dialect_(dialect) {}

  // PROTOs, nodes, IMPORT/EXPORT, then ROUTEs (after every DEF they name).
  void statements(const NodeDocument& document, int depth) {
    for (const auto& proto : document.protos) proto_declaration(proto, depth);
    for (const auto& root : document.roots) {
      indent(depth);
      node_statement(root, depth);
      out_ += "\n";
    }
    for (const auto& s : document.imports_exports) {
      indent(depth);
      out_ += s.import ? "IMPORT " + s.inline_def + "." + s.name : "EXPORT " + s.name;
      out_ += (s.as.empty() ? "" : " AS " + s.as) + "\n";
    }
    for (const auto& route : document.routes) {
      indent(depth);
      out_ += "ROUTE " + route.from_node + "." + route.from_field + " TO " + route.to_node + "." + route.to_field + "\n";
    }
  }

  void node_statement(const NodePtr& node, int depth) {
    if (!node) {
      out_ += "NULL";
      return;
    }
    if (!node->def_name.empty()) {
      if (written_.count(node.get())) {
        out_ += "USE " + node->def_name;
        return;
      }
      out_ += "DEF " + node->def_name + " ";
    }
    written_.insert(node.get());
    out_ += node->type;
    if (!node->declarations.empty() || !node->is_connections.empty()) {
      whole_node_body(*node, depth);
    } else if (node->fields.empty()) {
      out_ += " {}";
    } else if (!pretty_ || fits_one_line(*node)) {
      out_ += " {";
      for (const auto& field : node->fields) {
        out_ += " " + field.name + " ";
        value(field, depth);
      }
      out_ += " }";
    } else {
      out_ += " {\n";
      for (const auto& field : node->fields) {
        indent(depth + 1);
        out_ += field.name + " ";
        value(field, depth + 1);
        out_ += "\n";
      }
      indent(depth);
      out_ += "}";
    }
  }

 private:
  // A node with its own field declarations (Script) or IS connections (in a PROTO body): one item per
  // line; a declared field with its value or IS connection on the declaration.
  void whole_node_body(const Node& node, int depth) {
    out_ += " {\n";
    auto connection_of = [&](const std::string& field) -> const IsConnection* {
      for (const auto& c : node.is_connections)
        if (c.node_field == field) return &c;
      return nullptr;
    };
    std::set<std::string> done;
    for (const auto& d : node.declarations) {
      indent(depth + 1);
      out_ += access_keyword(d.access, dialect_) + " " + d.type_name + " " + d.name;
      if (const IsConnection* c = connection_of(d.name)) {
        out_ += " IS " + c->proto_field;
      } else if (const Field* f = node.find(d.name)) {
        out_ += " ";
        value(*f, depth + 1);
      }
      out_ += "\n";
      done.insert(d.name);
    }
    for (const auto& field : node.fields) {
      if (done.count(field.name)) continue;
      indent(depth + 1);
      out_ += field.name + " ";
      value(field, depth + 1);
      out_ += "\n";
    }
    for (const auto& c : node.is_connections) {
      if (done.count(c.node_field)) continue;
      indent(depth + 1);
      out_ += c.node_field + " IS " + c.proto_field + "\n";
    }
    indent(depth);
    out_ += "}";
  }

  void proto_declaration(const ProtoDeclaration& proto, int depth) {
    indent(depth);
    out_ += (proto.external ? "EXTERNPROTO " : "PROTO ") + proto.name + " [\n";
    for (const auto& d : proto.interface) {
      indent(depth + 1);
      out_ += access_keyword(d.access, dialect_) + " " + d.type_name + " " + d.name;
      if (d.default_value) {
        out_ += " ";
        ClassicWriter inner(out_, pretty_, dialect_);  // defaults have their own DEF names
        inner.value(Field{d.name, *d.default_value, {}, 0}, depth + 1);
      }
      out_ += "\n";
    }
    indent(depth);
    if (proto.external) {
      out_ += "] [";
      for (size_t i = 0; i < proto.urls.size(); ++i) out_ += (i ? " " : "") + quoted_string(proto.urls[i]);
      out_ += "]\n";
      return;
    }
    out_ += "] {\n";
    if (proto.body) ClassicWriter(out_, pretty_, dialect_).statements(*proto.body, depth + 1);
    indent(depth);
    out_ += "}\n";
  }

  // Small nodes (Appearance, Material, a short polyline) read best on one line.
  bool fits_one_line(const Node& node) const {
    for (const auto& field : node.fields) {
      if (std::holds_alternative<MFNode>(field.value)) return false;
      if (const auto* sf = std::get_if<SFNode>(&field.value)) {
        if (sf->node && (!fits_one_line(*sf->node) || sf->node->fields.size() > 2)) return false;
      } else if (const auto* strings = std::get_if<MFString>(&field.value)) {
        if (strings->values.size() > 3) return false;
      } else if (is_numeric_value(field.value) && number_count(field.value) > 4) {
        return false;
      }
    }
    return node.fields.size() <= 3;
  }

  void value(const Field& field, int depth) {
    const FieldValue& v = field.value;
    if (const auto* b = std::get_if<bool>(&v)) {
      out_ += *b ? "TRUE" : "FALSE";
    } else if (const auto* s = std::get_if<std::string>(&v)) {
      out_ += quoted_string(*s);
    } else if (const auto* strings = std::get_if<MFString>(&v)) {
      out_ += "[";
      for (size_t i = 0; i < strings->values.size(); ++i) out_ += (i ? " " : "") + quoted_string(strings->values[i]);
      out_ += "]";
    } else if (const auto* sf = std::get_if<SFNode>(&v)) {
      node_statement(sf->node, depth);
    } else if (const auto* mf = std::get_if<MFNode>(&v)) {
      out_ += "[\n";
      for (const auto& child : mf->nodes) {
        indent(depth + 1);
        node_statement(child, depth + 1);
        out_ += "\n";
      }
      indent(depth);
      out_ += "]";
    } else if (const auto* words = std::get_if<FieldWords>(&v)) {
      const bool multiple = words->type_name.starts_with("MF");
      if (multiple) out_ += "[";
      for (size_t i = 0; i < words->words.size(); ++i) out_ += (i ? " " : "") + words->words[i];
      if (multiple) out_ += "]";
    } else if (std::holds_alternative<MFFloat>(v) || std::holds_alternative<MFInt32>(v) ||
               std::holds_alternative<MFVec2f>(v) || std::holds_alternative<MFVec3f>(v)) {
      out_ += "[";
      append_numeric_value(out_, v, field.precision);
      out_ += "]";
    } else {
      append_numeric_value(out_, v, field.precision);
    }
  }

  void indent(int depth) {
    if (pretty_) out_.append(static_cast<size_t>(depth), ' ');
  }

  std::string& out_;
  bool pretty_;
  VrmlDialect dialect_;
  std::set<const Node*> written_;
};

}  // namespace

std::set<std::string> node_types_used(const NodeDocument& document) {
  std::set<std::string> types;
  for_each_node(document, [&](const Node& node) { types.insert(node.type); });
  return types;
}

std::string classic_encoding(const NodeDocument& document, const ClassicEncodingOptions& options) {
  std::string out;
  if (document.dialect == VrmlDialect::vrml97) {
    out += "#VRML V2.0 utf8\n";
    out += proto_declarations(document, options);
  } else {
    out += "#X3D V3.3 utf8\nPROFILE " + document.profile + "\nCOMPONENT NURBS:4\n";
  }
  ClassicWriter(out, options.pretty, document.dialect).statements(document, 0);
  return out;
}

}  // namespace cadnurbs
