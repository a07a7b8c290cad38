#include "formats/vrml/xml_parser.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <map>

#include "core/chars_to_double.hpp"
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
      if (child.name == "head") {
        for (const auto& h : child.children)
          if (h.name == "unit") fail("<unit> statements are not read: they change the units of the numbers", h.line);
        continue;
      }
      if (child.name != "Scene") fail("unexpected <" + child.name + "> in <X3D>", child.line);
      for (const auto& e : child.children)
        if (!statement(e, document)) document.roots.push_back(node(e));
    }
    return document;
  }

 private:
  const std::string& required(const XmlElement& e, const char* name) const {
    const XmlAttribute* a = e.attribute(name);
    if (!a) fail("<" + e.name + "> needs a " + name + " attribute", e.line);
    return a->value;
  }

  // ROUTE, IMPORT, EXPORT, ProtoDeclare and ExternProtoDeclare: recorded (a PROTO's body is not read).
  // False: a node.
  bool statement(const XmlElement& e, NodeDocument& document) {
    if (e.name == "ROUTE") {
      document.routes.push_back(Route{required(e, "fromNode"), required(e, "fromField"), required(e, "toNode"),
                                      required(e, "toField"), e.line});
      return true;
    }
    if (e.name == "IMPORT" || e.name == "EXPORT") {
      ImportExport statement;
      statement.import = e.name == "IMPORT";
      if (statement.import) {
        statement.inline_def = required(e, "inlineDEF");
        statement.name = required(e, "importedDEF");
      } else {
        statement.name = required(e, "localDEF");
      }
      if (const auto* as = e.attribute("AS")) statement.as = as->value;
      document.imports_exports.push_back(std::move(statement));
      return true;
    }
    if (e.name == "ProtoDeclare" || e.name == "ExternProtoDeclare") {
      const bool external = e.name == "ExternProtoDeclare";
      ProtoDeclaration proto{required(e, "name"), external, {}, {}, nullptr, e.line};
      NodeSchema schema{proto.name, "children", {}};
      const XmlElement* interface = &e;
      const XmlElement* body = nullptr;
      if (!external) {
        interface = nullptr;
        for (const auto& c : e.children) {
          if (c.name == "ProtoInterface") interface = &c;
          if (c.name == "ProtoBody") body = &c;
        }
      } else if (const auto* url = e.attribute("url")) {
        proto.urls = strings(*url).values;
      }
      // A PROTO's defaults and body are in its own DEF name scope.
      auto outer_defs = std::move(defs_);
      defs_.clear();
      if (interface)
        for (const auto& f : interface->children) {
          if (f.name != "field") fail("unexpected <" + f.name + "> in the interface of " + proto.name, f.line);
          InterfaceDeclaration d;
          schema.fields.push_back(declaration(f, d));
          if (const auto* v = f.attribute("value")) d.default_value = attribute_value(schema.fields.back(), *v);
          for (const auto& n : f.children) {
            Node holder;
            add_child(holder, schema.fields.back(), this->node(n), n.line);
            d.default_value = holder.fields.front().value;
          }
          proto.interface.push_back(std::move(d));
        }
      proto_schemas_[proto.name] = schema;
      if (body) {
        const auto outer_protos = proto_schemas_;
        ++body_depth_;
        NodeDocument inside;
        inside.dialect = VrmlDialect::x3d;
        for (const auto& c : body->children)
          if (!statement(c, inside)) inside.roots.push_back(node(c));
        --body_depth_;
        proto_schemas_ = outer_protos;
        proto.body = std::make_shared<NodeDocument>(std::move(inside));
      }
      defs_ = std::move(outer_defs);
      document.protos.push_back(std::move(proto));
      return true;
    }
    return false;
  }

  // <IS><connect nodeField protoField/>...</IS> of a node in a PROTO body.
  void is_connections(const XmlElement& is, Node& node) {
    if (body_depth_ == 0) fail("IS outside a PROTO body", is.line);
    for (const auto& c : is.children) {
      if (c.name != "connect") fail("unexpected <" + c.name + "> in <IS>", c.line);
      node.is_connections.push_back(IsConnection{required(c, "nodeField"), required(c, "protoField")});
    }
  }

  // <field name type accessType [value]/> of a PROTO interface or a Script.
  FieldSchema declaration(const XmlElement& f, InterfaceDeclaration& out) const {
    const std::string& name = required(f, "name");
    const std::string& type = required(f, "type");
    const std::string& access_name = required(f, "accessType");
    const auto access = declaration_access(access_name);
    if (!access) fail("accessType '" + access_name + "' of field " + name + " is not an access type", f.line);
    auto schema = declared_field(name, type, *access);
    if (!schema) fail("'" + type + "' of field " + name + " is not a field type", f.line);
    out = InterfaceDeclaration{access_name, type, name, std::nullopt};
    return *schema;
  }


  // A field value given by attribute (or by a <fieldValue> / <field> element's value attribute).
  void add_attribute_field(Node& node, const FieldSchema& f, const XmlAttribute& a) {
    if (f.type == FieldType::SFNode || f.type == FieldType::MFNode)
      fail("field " + f.name + " holds nodes; give it as a child element", a.line);
    if (f.access == FieldAccess::input_only || f.access == FieldAccess::output_only)
      fail("field " + f.name + " of " + node.type + " is an event: it has no value", a.line);
    if (node.find(f.name)) fail("field " + f.name + " of " + node.type + " is given twice", a.line);
    node.fields.push_back(Field{f.name, attribute_value(f, a), {}, a.line});
  }

  // Appends a child node to node field `container` of `node`.
  void add_child(Node& node, const FieldSchema& f, NodePtr child, int line) {
    Field* field = nullptr;
    for (auto& existing : node.fields)
      if (existing.name == f.name) field = &existing;
    if (f.type == FieldType::SFNode) {
      if (field) fail("field " + f.name + " of " + node.type + " is given twice", line);
      node.fields.push_back(Field{f.name, SFNode{std::move(child)}, {}, line});
      return;
    }
    if (!field) {
      node.fields.push_back(Field{f.name, MFNode{}, {}, line});
      field = &node.fields.back();
    }
    std::get<MFNode>(field->value).nodes.push_back(std::move(child));
  }

  NodePtr node(const XmlElement& e) {
    if (const auto* use = e.attribute("USE")) {
      auto it = defs_.find(use->value);
      if (it == defs_.end()) fail("USE='" + use->value + "' before any DEF='" + use->value + "'", use->line);
      return it->second;
    }
    if (e.name == "ProtoInstance") return proto_instance(e);
    const NodeSchema* schema = node_schema(VrmlDialect::x3d, e.name);
    if (!schema) fail("unknown node " + e.name + " (not an X3D node; a PROTO is used by <ProtoInstance>)", e.line);
    NodePtr node = make_node(e.name);
    node->line = e.line;
    std::vector<FieldSchema> declared;  // a Script's own fields
    if (declares_own_fields(e.name))
      for (const auto& c : e.children)
        if (c.name == "field") {
          InterfaceDeclaration d;
          declared.push_back(declaration(c, d));
          node->declarations.push_back(std::move(d));
          if (const auto* v = c.attribute("value")) add_attribute_field(*node, declared.back(), *v);
          for (const auto& n : c.children) {
            if (n.name == "IS") is_connections(n, *node);
            else add_child(*node, declared.back(), this->node(n), n.line);
          }
        }
    // A Script's source in CDATA is one of its urls, the first.
    if (e.name == "Script" && e.cdata.find_first_not_of(" \t\r\n") != std::string::npos) {
      MFString url{{e.cdata}};
      if (const auto* given = e.attribute("url")) {
        const MFString more = strings(*given);
        url.values.insert(url.values.end(), more.values.begin(), more.values.end());
      }
      node->fields.push_back(Field{"url", std::move(url), {}, e.line});
    }
    for (const auto& a : e.attributes) {
      if (a.name == "DEF") {
        node->def_name = a.value;
        continue;
      }
      if (a.name == "containerField" || a.name == "class" || a.name == "id" || a.name == "style") continue;
      if (a.name == "url" && e.name == "Script" && node->find("url")) continue;  // joined with the CDATA above
      const FieldSchema* f = find_field(*schema, a.name);
      if (!f) fail(e.name + " has no field " + a.name, a.line);
      add_attribute_field(*node, *f, a);
    }
    for (const auto& c : e.children) {
      if (c.name == "field" && declares_own_fields(e.name)) continue;
      if (c.name == "IS") {
        is_connections(c, *node);
        continue;
      }
      NodePtr child = this->node(c);
      std::string container;
      if (const auto* cf = c.attribute("containerField")) container = cf->value;
      else if (const NodeSchema* child_schema = node_schema(VrmlDialect::x3d, child->type))
        container = child_schema->container_field;
      else container = "children";
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
      add_child(*node, *find_field(*schema, container), std::move(child), c.line);
    }
    // Known to USE only after its children: a node cannot contain itself.
    if (!node->def_name.empty()) defs_[node->def_name] = node;
    return node;
  }

  // <ProtoInstance name DEF> with <fieldValue name value/> (or with node children).
  NodePtr proto_instance(const XmlElement& e) {
    const std::string& name = required(e, "name");
    const auto proto = proto_schemas_.find(name);
    if (proto == proto_schemas_.end()) fail("ProtoInstance of " + name + " before its declaration", e.line);
    NodePtr node = make_node(name);
    node->line = e.line;
    node->proto_instance = true;
    if (const auto* def = e.attribute("DEF")) node->def_name = def->value;
    for (const auto& c : e.children) {
      if (c.name == "IS") {
        is_connections(c, *node);
        continue;
      }
      if (c.name != "fieldValue") fail("unexpected <" + c.name + "> in a ProtoInstance", c.line);
      const std::string& field_name = required(c, "name");
      const FieldSchema* f = find_field(proto->second, field_name);
      if (!f) fail(name + " has no field " + field_name, c.line);
      if (const auto* v = c.attribute("value")) add_attribute_field(*node, *f, *v);
      for (const auto& n : c.children) add_child(*node, *f, this->node(n), n.line);
    }
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
      const auto r = chars_to_double(first, s.data() + j, v);
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

  // The words of an attribute of a FieldWords type: numbers and true/false (written TRUE/FALSE, as
  // the classic encoding does).
  FieldWords words(const FieldSchema& f, const XmlAttribute& a) const {
    FieldWords out{f.type_name, {}};
    std::string word;
    auto flush = [&] {
      if (word.empty()) return;
      if (word == "true") word = "TRUE";
      if (word == "false") word = "FALSE";
      out.words.push_back(word);
      word.clear();
    };
    for (char c : a.value) {
      if (std::isspace(static_cast<unsigned char>(c)) || c == ',') flush();
      else word.push_back(c);
    }
    flush();
    const int per_value = words_per_value(f.type_name);
    if (per_value > 0 && out.words.size() % per_value != 0)
      fail("field " + a.name + " has " + std::to_string(out.words.size()) + " numbers, not a multiple of " +
               std::to_string(per_value),
           a.line);
    if (f.type == FieldType::SFWords && per_value > 0 && out.words.size() != static_cast<size_t>(per_value))
      fail("field " + a.name + " needs " + std::to_string(per_value) + " numbers", a.line);
    return out;
  }

  FieldValue attribute_value(const FieldSchema& f, const XmlAttribute& a) const {
    if (f.type == FieldType::SFWords || f.type == FieldType::MFWords) return words(f, a);
    switch (f.type) {
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
      case FieldType::MFNode:
      case FieldType::SFWords:
      case FieldType::MFWords: break;
    }
    fail("field " + a.name + " cannot be an attribute", a.line);
  }

  [[noreturn]] void fail(const std::string& reason, int line) const { throw_parse_error(file_, line, reason); }

  const std::string& file_;
  std::map<std::string, NodePtr> defs_;
  std::map<std::string, NodeSchema> proto_schemas_;
  int body_depth_ = 0;  // inside PROTO bodies: IS is allowed
};

}  // namespace

NodeDocument parse_xml(const std::string& text, const std::string& name_for_errors) {
  return X3dBuilder(name_for_errors).document(parse_xml_markup(text, name_for_errors));
}

}  // namespace cadnurbs
