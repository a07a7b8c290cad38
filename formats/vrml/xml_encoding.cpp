#include "formats/vrml/xml_encoding.hpp"

#include <set>
#include <stdexcept>

#include "formats/vrml/node_schema.hpp"
#include "formats/vrml/node_text.hpp"

namespace cadnurbs {

namespace {

class XmlWriter {
 public:
  XmlWriter(std::string& out, bool pretty) : out_(out), pretty_(pretty) {}

  // PROTOs, nodes, IMPORT/EXPORT, then ROUTEs (after every DEF they name).
  void statements(const NodeDocument& document, int depth) {
    for (const auto& proto : document.protos) proto_declaration(proto, depth);
    for (const auto& root : document.roots) element(root, "", depth);
    for (const auto& s : document.imports_exports) {
      indent(depth);
      if (s.import)
        out_ += "<IMPORT inlineDEF='" + xml_escaped(s.inline_def) + "' importedDEF='" + xml_escaped(s.name) + "'";
      else
        out_ += "<EXPORT localDEF='" + xml_escaped(s.name) + "'";
      if (!s.as.empty()) out_ += " AS='" + xml_escaped(s.as) + "'";
      out_ += "/>\n";
    }
    for (const auto& r : document.routes) {
      indent(depth);
      out_ += "<ROUTE fromNode='" + xml_escaped(r.from_node) + "' fromField='" + xml_escaped(r.from_field) +
              "' toNode='" + xml_escaped(r.to_node) + "' toField='" + xml_escaped(r.to_field) + "'/>\n";
    }
  }

  void element(const NodePtr& node, const std::string& container_field, int depth) {
    if (!node) return;  // NULL: the field keeps its default
    if (node->proto_instance || !node->declarations.empty() || !node->is_connections.empty()) {
      whole_element(node, container_field, depth);
      return;
    }
    if (!open_tag(node, node->type, container_field, depth)) return;
    bool has_children = false;
    for (const auto& field : node->fields) {
      if (std::holds_alternative<SFNode>(field.value) || std::holds_alternative<MFNode>(field.value)) {
        has_children = has_children || node_count(field.value) > 0;
        continue;
      }
      out_ += " " + field.name + "='";
      attribute(field);
      out_ += "'";
    }
    if (!has_children) {
      out_ += "/>\n";
      return;
    }
    out_ += ">\n";
    for (const auto& field : node->fields) {
      if (const auto* sf = std::get_if<SFNode>(&field.value)) element(sf->node, field.name, depth + 1);
      if (const auto* mf = std::get_if<MFNode>(&field.value))
        for (const auto& child : mf->nodes) element(child, field.name, depth + 1);
    }
    indent(depth);
    out_ += "</" + node->type + ">\n";
  }

 private:
  // "<tag" with the PROTO's name, containerField where it is not the default, and DEF; false when the
  // node was written before and "USE='...'/>" closed it.
  bool open_tag(const NodePtr& node, const std::string& tag, const std::string& container_field, int depth) {
    indent(depth);
    out_ += "<" + tag;
    const bool instance = node->proto_instance;
    if (instance) out_ += " name='" + xml_escaped(node->type) + "'";
    const NodeSchema* schema = instance ? nullptr : node_schema(VrmlDialect::x3d, node->type);
    if (!container_field.empty() && (!schema || schema->container_field != container_field))
      out_ += " containerField='" + container_field + "'";
    if (!node->def_name.empty()) {
      if (written_.count(node.get())) {
        out_ += " USE='" + node->def_name + "'/>\n";
        return false;
      }
      out_ += " DEF='" + node->def_name + "'";
    }
    written_.insert(node.get());
    return true;
  }

  // A PROTO instance (<ProtoInstance> with <fieldValue>s), a Script with its <field> declarations, or a
  // node with IS connections (<IS><connect/></IS>).
  void whole_element(const NodePtr& node, const std::string& container_field, int depth) {
    const bool instance = node->proto_instance;
    const std::string tag = instance ? "ProtoInstance" : node->type;
    if (!open_tag(node, tag, container_field, depth)) return;
    std::set<std::string> declared;
    for (const auto& d : node->declarations) declared.insert(d.name);
    // Plain fields as attributes (not on a ProtoInstance).
    if (!instance)
      for (const auto& field : node->fields)
        if (!declared.count(field.name) && !holds_nodes(field.value)) {
          out_ += " " + field.name + "='";
          attribute(field);
          out_ += "'";
        }
    out_ += ">\n";
    for (const auto& d : node->declarations) {
      indent(depth + 1);
      out_ += "<field name='" + xml_escaped(d.name) + "' type='" + d.type_name + "' accessType='" +
              access_keyword(d.access, VrmlDialect::x3d) + "'";
      const Field* f = node->find(d.name);
      if (f && !holds_nodes(f->value)) {
        out_ += " value='";
        attribute(*f);
        out_ += "'";
      }
      if (f && holds_nodes(f->value) && node_count(f->value) > 0) {
        out_ += ">\n";
        children(*f, "", depth + 2);
        indent(depth + 1);
        out_ += "</field>\n";
      } else {
        out_ += "/>\n";
      }
    }
    if (instance)
      for (const auto& field : node->fields) {
        indent(depth + 1);
        out_ += "<fieldValue name='" + xml_escaped(field.name) + "'";
        if (!holds_nodes(field.value)) {
          out_ += " value='";
          attribute(field);
          out_ += "'/>\n";
          continue;
        }
        out_ += ">\n";
        children(field, "", depth + 2);
        indent(depth + 1);
        out_ += "</fieldValue>\n";
      }
    else
      for (const auto& field : node->fields)
        if (!declared.count(field.name) && holds_nodes(field.value)) children(field, field.name, depth + 1);
    if (!node->is_connections.empty()) {
      indent(depth + 1);
      out_ += "<IS>\n";
      for (const auto& c : node->is_connections) {
        indent(depth + 2);
        out_ += "<connect nodeField='" + xml_escaped(c.node_field) + "' protoField='" + xml_escaped(c.proto_field) + "'/>\n";
      }
      indent(depth + 1);
      out_ += "</IS>\n";
    }
    indent(depth);
    out_ += "</" + tag + ">\n";
  }

  void children(const Field& field, const std::string& container_field, int depth) {
    if (const auto* sf = std::get_if<SFNode>(&field.value)) element(sf->node, container_field, depth);
    if (const auto* mf = std::get_if<MFNode>(&field.value))
      for (const auto& child : mf->nodes) element(child, container_field, depth);
  }

  static bool holds_nodes(const FieldValue& value) {
    return std::holds_alternative<SFNode>(value) || std::holds_alternative<MFNode>(value);
  }

  void proto_declaration(const ProtoDeclaration& proto, int depth) {
    indent(depth);
    if (proto.external) {
      out_ += "<ExternProtoDeclare name='" + xml_escaped(proto.name) + "' url='";
      for (size_t i = 0; i < proto.urls.size(); ++i) out_ += (i ? " " : "") + xml_escaped(quoted_string(proto.urls[i]));
      out_ += "'>\n";
    } else {
      out_ += "<ProtoDeclare name='" + xml_escaped(proto.name) + "'>\n";
      indent(depth + 1);
      out_ += "<ProtoInterface>\n";
    }
    const int field_depth = proto.external ? depth + 1 : depth + 2;
    for (const auto& d : proto.interface) {
      indent(field_depth);
      out_ += "<field name='" + xml_escaped(d.name) + "' type='" + d.type_name + "' accessType='" +
              access_keyword(d.access, VrmlDialect::x3d) + "'";
      if (d.default_value && !holds_nodes(*d.default_value)) {
        out_ += " value='";
        attribute(Field{d.name, *d.default_value, {}, 0});
        out_ += "'/>\n";
      } else if (d.default_value && node_count(*d.default_value) > 0) {
        out_ += ">\n";
        XmlWriter inner(out_, pretty_);  // defaults have their own DEF names
        inner.children(Field{d.name, *d.default_value, {}, 0}, "", field_depth + 1);
        indent(field_depth);
        out_ += "</field>\n";
      } else {
        out_ += "/>\n";
      }
    }
    if (proto.external) {
      indent(depth);
      out_ += "</ExternProtoDeclare>\n";
      return;
    }
    indent(depth + 1);
    out_ += "</ProtoInterface>\n";
    indent(depth + 1);
    out_ += "<ProtoBody>\n";
    if (proto.body) XmlWriter(out_, pretty_).statements(*proto.body, depth + 2);
    indent(depth + 1);
    out_ += "</ProtoBody>\n";
    indent(depth);
    out_ += "</ProtoDeclare>\n";
  }

  static size_t node_count(const FieldValue& value) {
    if (const auto* sf = std::get_if<SFNode>(&value)) return sf->node ? 1 : 0;
    return std::get<MFNode>(value).nodes.size();
  }

  void attribute(const Field& field) {
    const FieldValue& v = field.value;
    if (const auto* b = std::get_if<bool>(&v)) {
      out_ += *b ? "true" : "false";
    } else if (const auto* s = std::get_if<std::string>(&v)) {
      out_ += xml_escaped(*s);
    } else if (const auto* strings = std::get_if<MFString>(&v)) {
      for (size_t i = 0; i < strings->values.size(); ++i)
        out_ += (i ? " " : "") + xml_escaped(quoted_string(strings->values[i]));
    } else if (const auto* words = std::get_if<FieldWords>(&v)) {
      for (size_t i = 0; i < words->words.size(); ++i) {
        const std::string& w = words->words[i];
        out_ += (i ? " " : "") + (w == "TRUE" ? std::string("true") : w == "FALSE" ? std::string("false") : w);
      }
    } else {
      append_numeric_value(out_, v, field.precision);
    }
  }

  void indent(int depth) {
    if (pretty_) out_.append(static_cast<size_t>(depth), ' ');
  }

  std::string& out_;
  bool pretty_;
  std::set<const Node*> written_;
};

}  // namespace

std::string xml_escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '\'': out += "&apos;"; break;
      case '\n': out += "&#10;"; break;
      case '\r': out += "&#13;"; break;
      case '\t': out += "&#9;"; break;
      default: out.push_back(c);
    }
  }
  return out;
}

std::string xml_encoding(const NodeDocument& document, bool pretty) {
  if (document.dialect != VrmlDialect::x3d)
    throw std::invalid_argument("the VRML97 NURBS nodes have no X3D XML encoding");
  std::string out =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<X3D profile='" + document.profile + "' version='3.3'>\n"
      "<head>\n"
      "<component name='NURBS' level='4'/>\n"
      "</head>\n"
      "<Scene>\n";
  XmlWriter(out, pretty).statements(document, 0);
  out += "</Scene>\n</X3D>\n";
  return out;
}

}  // namespace cadnurbs
