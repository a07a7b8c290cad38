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

  void element(const NodePtr& node, const std::string& container_field, int depth) {
    if (!node) return;  // NULL: the field keeps its default
    indent(depth);
    out_ += "<" + node->type;
    const NodeSchema* schema = node_schema(VrmlDialect::x3d, node->type);
    if (!container_field.empty() && (!schema || schema->container_field != container_field))
      out_ += " containerField='" + container_field + "'";
    if (!node->def_name.empty()) {
      if (written_.count(node.get())) {
        out_ += " USE='" + node->def_name + "'/>\n";
        return;
      }
      out_ += " DEF='" + node->def_name + "'";
    }
    written_.insert(node.get());
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
      "<X3D profile='Interchange' version='3.3'>\n"
      "<head>\n"
      "<component name='NURBS' level='4'/>\n"
      "</head>\n"
      "<Scene>\n";
  XmlWriter writer(out, pretty);
  for (const auto& root : document.roots) writer.element(root, "", 0);
  out += "</Scene>\n</X3D>\n";
  return out;
}

}  // namespace cadnurbs
