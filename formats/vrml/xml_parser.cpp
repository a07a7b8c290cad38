#include "formats/vrml/xml_parser.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <map>

#include "formats/vrml/field_integer.hpp"
#include "formats/vrml/node_schema.hpp"
#include "formats/vrml/parse_error.hpp"
#include "formats/vrml/xml_markup.hpp"

namespace cadnurbs {

namespace {

// Elements to nodes.
class X3dBuilder {
 public:
  explicit X3dBuilder(const std::string& file) : file_(file) {}

  NodeDocument document(const XmlElement& root) {
    if (root.name != "X3D") fail("the root element is <" + root.name + ">, not <X3D>", root.line);
    NodeDocument document;
    document.dialect = VrmlDialect::x3d;
    for (const auto& child : root.children) {
      if (child.name == "head") continue;
      if (child.name != "Scene") fail("unexpected <" + child.name + "> in <X3D>", child.line);
      for (const auto& e : child.children) document.roots.push_back(node(e));
    }
    return document;
  }

 private:
  NodePtr node(const XmlElement& e) {
    if (const auto* use = e.attribute("USE")) {
      auto it = defs_.find(use->value);
      if (it == defs_.end()) fail("USE='" + use->value + "' before any DEF='" + use->value + "'", use->line);
      return it->second;
    }
    const NodeSchema* schema = node_schema(VrmlDialect::x3d, e.name);
    if (!schema) fail("unsupported node " + e.name + " (outside the X3D subset cadnurbs reads)", e.line);
    NodePtr node = make_node(e.name);
    node->line = e.line;
    for (const auto& a : e.attributes) {
      if (a.name == "DEF") {
        node->def_name = a.value;
        continue;
      }
      if (a.name == "containerField" || a.name == "class") continue;
      const auto type = field_type(*schema, a.name);
      if (!type) fail(e.name + " has no field " + a.name + " in the subset cadnurbs reads", a.line);
      if (*type == FieldType::SFNode || *type == FieldType::MFNode)
        fail("field " + a.name + " holds nodes; give it as a child element", a.line);
      node->fields.push_back(Field{a.name, value(*type, a), {}, a.line});
    }
    for (const auto& c : e.children) {
      NodePtr child = this->node(c);
      std::string container;
      if (const auto* cf = c.attribute("containerField")) container = cf->value;
      else container = std::string(node_schema(VrmlDialect::x3d, child->type)->container_field);
      auto type = field_type(*schema, container);
      // Files disagree on some defaults (ContourPolyline2D): a parent without that field takes the child
      // among its children.
      if (!c.attribute("containerField") && (!type || (*type != FieldType::SFNode && *type != FieldType::MFNode)) &&
          field_type(*schema, "children") == FieldType::MFNode) {
        container = "children";
        type = FieldType::MFNode;
      }
      if (!type || (*type != FieldType::SFNode && *type != FieldType::MFNode))
        fail(e.name + " has no node field " + container + " for <" + c.name + ">", c.line);
      Field* field = nullptr;
      for (auto& f : node->fields)
        if (f.name == container) field = &f;
      if (*type == FieldType::SFNode) {
        if (field) fail("field " + container + " of " + e.name + " is given twice", c.line);
        node->fields.push_back(Field{container, SFNode{child}, {}, c.line});
      } else {
        if (!field) {
          node->fields.push_back(Field{container, MFNode{}, {}, c.line});
          field = &node->fields.back();
        }
        std::get<MFNode>(field->value).nodes.push_back(child);
      }
    }
    // Known to USE only after its children: a node cannot contain itself.
    if (!node->def_name.empty()) defs_[node->def_name] = node;
    return node;
  }

  std::vector<double> numbers(const XmlAttribute& a, size_t arity) const {
    std::vector<double> out;
    const std::string& s = a.value;
    for (size_t i = 0; i < s.size();) {
      if (std::isspace(static_cast<unsigned char>(s[i])) || s[i] == ',') {
        ++i;
        continue;
      }
      size_t j = i;
      while (j < s.size() && !std::isspace(static_cast<unsigned char>(s[j])) && s[j] != ',') ++j;
      const char* first = s.data() + i + (s[i] == '+' ? 1 : 0);
      double v = 0.0;
      const auto r = std::from_chars(first, s.data() + j, v);
      if (r.ec != std::errc() || r.ptr != s.data() + j || !std::isfinite(v))
        fail("field " + a.name + ": '" + s.substr(i, j - i) + "' is not a finite number", a.line);
      out.push_back(v);
      i = j;
    }
    if (out.size() % arity != 0)
      fail("field " + a.name + " has " + std::to_string(out.size()) + " numbers, not a multiple of " +
                       std::to_string(arity),
                   a.line);
    return out;
  }

  std::vector<double> exactly(const XmlAttribute& a, size_t count) const {
    auto v = numbers(a, 1);
    if (v.size() != count) fail("field " + a.name + " needs " + std::to_string(count) + " numbers", a.line);
    return v;
  }

  int integer(const XmlAttribute& a, double v) const {
    const std::optional<int> value = field_integer(v);
    if (!value) fail("field " + a.name + ": expected integers", a.line);
    return *value;
  }

  MFString strings(const XmlAttribute& a) const {
    MFString out;
    const std::string& s = a.value;
    size_t i = s.find_first_not_of(" \t\r\n,");
    if (i == std::string::npos) return out;
    if (s[i] != '"') {  // unquoted: one string (lenient; X3D asks for quotes)
      out.values.push_back(s.substr(i));
      return out;
    }
    while (i != std::string::npos) {
      if (s[i] != '"') fail("field " + a.name + ": expected a quoted string", a.line);
      std::string value;
      size_t j = i + 1;
      for (; j < s.size() && s[j] != '"'; ++j) {
        if (s[j] == '\\' && j + 1 < s.size()) ++j;
        value.push_back(s[j]);
      }
      if (j >= s.size()) fail("field " + a.name + ": string is not terminated", a.line);
      out.values.push_back(value);
      i = s.find_first_not_of(" \t\r\n,", j + 1);
    }
    return out;
  }

  FieldValue value(FieldType type, const XmlAttribute& a) const {
    switch (type) {
      case FieldType::SFBool:
        if (a.value == "true" || a.value == "TRUE") return true;
        if (a.value == "false" || a.value == "FALSE") return false;
        fail("field " + a.name + ": expected true or false", a.line);
      case FieldType::SFInt32: return integer(a, exactly(a, 1)[0]);
      case FieldType::SFFloat: return exactly(a, 1)[0];
      case FieldType::SFString: return a.value;
      case FieldType::MFFloat: return MFFloat{numbers(a, 1)};
      case FieldType::MFInt32: {
        MFInt32 out;
        for (double v : numbers(a, 1)) out.values.push_back(integer(a, v));
        return out;
      }
      case FieldType::MFVec2f: {
        const auto v = numbers(a, 2);
        MFVec2f out;
        for (size_t i = 0; i < v.size(); i += 2) out.values.emplace_back(v[i], v[i + 1]);
        return out;
      }
      case FieldType::MFVec3f: {
        const auto v = numbers(a, 3);
        MFVec3f out;
        for (size_t i = 0; i < v.size(); i += 3) out.values.emplace_back(v[i], v[i + 1], v[i + 2]);
        return out;
      }
      case FieldType::MFString: return strings(a);
      case FieldType::SFColor: {
        const auto v = exactly(a, 3);
        return SFColor{Eigen::Vector3d(v[0], v[1], v[2])};
      }
      case FieldType::SFVec3f: {
        const auto v = exactly(a, 3);
        return SFVec3f{Eigen::Vector3d(v[0], v[1], v[2])};
      }
      case FieldType::SFRotation: {
        const auto v = exactly(a, 4);
        return SFRotation{Eigen::Vector3d(v[0], v[1], v[2]), v[3]};
      }
      case FieldType::SFNode:
      case FieldType::MFNode: break;
    }
    fail("field " + a.name + " cannot be an attribute", a.line);
  }

  [[noreturn]] void fail(const std::string& reason, int line) const { throw_parse_error(file_, line, reason); }

  const std::string& file_;
  std::map<std::string, NodePtr> defs_;
};

}  // namespace

NodeDocument parse_xml(const std::string& text, const std::string& name_for_errors) {
  return X3dBuilder(name_for_errors).document(parse_xml_markup(text, name_for_errors));
}

}  // namespace cadnurbs
