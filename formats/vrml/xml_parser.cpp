#include "formats/vrml/xml_parser.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <map>

#include "formats/common/file_io.hpp"
#include "formats/vrml/node_schema.hpp"

namespace cadnurbs {

namespace {

struct XmlAttribute {
  std::string name, value;
  int line = 0;
};

struct XmlElement {
  std::string name;
  std::vector<XmlAttribute> attributes;
  std::vector<XmlElement> children;
  int line = 0;

  const XmlAttribute* attribute(const std::string& n) const {
    for (const auto& a : attributes)
      if (a.name == n) return &a;
    return nullptr;
  }
};

void append_utf8(std::string& out, unsigned long code) {
  if (code < 0x80) {
    out.push_back(static_cast<char>(code));
  } else if (code < 0x800) {
    out.push_back(static_cast<char>(0xC0 | (code >> 6)));
    out.push_back(static_cast<char>(0x80 | (code & 0x3F)));
  } else if (code < 0x10000) {
    out.push_back(static_cast<char>(0xE0 | (code >> 12)));
    out.push_back(static_cast<char>(0x80 | ((code >> 6) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | (code & 0x3F)));
  } else {
    out.push_back(static_cast<char>(0xF0 | (code >> 18)));
    out.push_back(static_cast<char>(0x80 | ((code >> 12) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | ((code >> 6) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | (code & 0x3F)));
  }
}

// Elements and attributes: the markup layer.
class XmlReader {
 public:
  XmlReader(const std::string& text, const std::string& name) : text_(text), name_(name) {}

  XmlElement document() {
    if (text_.compare(0, 3, "\xEF\xBB\xBF") == 0) position_ = 3;
    skip_misc();
    if (position_ >= text_.size() || text_[position_] != '<') fail("not an XML file");
    XmlElement root = element();
    skip_misc();
    if (position_ < text_.size()) fail("content after the root element");
    return root;
  }

  [[noreturn]] void fail(const std::string& reason, int line = 0) const {
    throw FileError(name_ + ": line " + std::to_string(line ? line : line_) + ": " + reason);
  }

 private:
  bool at(const char* s) const { return text_.compare(position_, std::char_traits<char>::length(s), s) == 0; }

  void advance(size_t n) {
    for (size_t i = 0; i < n && position_ < text_.size(); ++i)
      if (text_[position_++] == '\n') ++line_;
  }

  void skip_to(const char* terminator, const char* what) {
    const size_t end = text_.find(terminator, position_);
    if (end == std::string::npos) fail(std::string(what) + " is not terminated");
    advance(end - position_ + std::char_traits<char>::length(terminator));
  }

  void skip_space() {
    while (position_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[position_]))) advance(1);
  }

  // Declarations, processing instructions, comments, DOCTYPE and text between elements.
  void skip_misc() {
    for (;;) {
      skip_space();
      if (at("<?")) {
        skip_to("?>", "processing instruction");
      } else if (at("<!--")) {
        skip_to("-->", "comment");
      } else if (at("<![CDATA[")) {
        fail("CDATA sections (scripts) are outside the subset cadnurbs reads");
      } else if (at("<!")) {
        int depth = 0;
        while (position_ < text_.size() && !(text_[position_] == '>' && depth == 0)) {
          if (text_[position_] == '[') ++depth;
          if (text_[position_] == ']') --depth;
          advance(1);
        }
        if (position_ >= text_.size()) fail("declaration is not terminated");
        advance(1);
      } else if (position_ < text_.size() && text_[position_] != '<') {
        while (position_ < text_.size() && text_[position_] != '<') advance(1);  // character data: ignored
      } else {
        return;
      }
    }
  }

  std::string name_token() {
    const size_t start = position_;
    while (position_ < text_.size()) {
      const char c = text_[position_];
      if (std::isspace(static_cast<unsigned char>(c)) || c == '=' || c == '>' || c == '/' || c == '<' || c == '\'' ||
          c == '"')
        break;
      advance(1);
    }
    if (position_ == start) fail("expected a name");
    return text_.substr(start, position_ - start);
  }

  std::string decoded(const std::string& raw, int line) const {
    std::string out;
    for (size_t i = 0; i < raw.size(); ++i) {
      if (raw[i] != '&') {
        out.push_back(raw[i]);
        continue;
      }
      const size_t end = raw.find(';', i);
      if (end == std::string::npos) fail("'&' without ';'", line);
      const std::string entity = raw.substr(i + 1, end - i - 1);
      if (entity == "lt") out.push_back('<');
      else if (entity == "gt") out.push_back('>');
      else if (entity == "amp") out.push_back('&');
      else if (entity == "quot") out.push_back('"');
      else if (entity == "apos") out.push_back('\'');
      else if (entity.size() > 1 && entity[0] == '#') {
        const bool hex = entity[1] == 'x' || entity[1] == 'X';
        unsigned long code = 0;
        const char* first = entity.data() + (hex ? 2 : 1);
        const auto r = std::from_chars(first, entity.data() + entity.size(), code, hex ? 16 : 10);
        if (r.ec != std::errc() || r.ptr != entity.data() + entity.size() || code > 0x10FFFF)
          fail("bad character reference &" + entity + ";", line);
        append_utf8(out, code);
      } else {
        fail("unknown entity &" + entity + ";", line);
      }
      i = end;
    }
    return out;
  }

  XmlElement element() {
    XmlElement e;
    e.line = line_;
    // Recursion guard: far deeper than any real scene, far shallower than the stack.
    if (++depth_ > 1000) fail("elements nested deeper than 1000 levels");
    advance(1);  // '<'
    e.name = name_token();
    for (;;) {
      skip_space();
      if (position_ >= text_.size()) fail("element <" + e.name + "> is not terminated", e.line);
      if (at("/>")) {
        advance(2);
        --depth_;
        return e;
      }
      if (text_[position_] == '>') {
        advance(1);
        break;
      }
      XmlAttribute a;
      a.line = line_;
      a.name = name_token();
      skip_space();
      if (!at("=")) fail("attribute " + a.name + " has no value");
      advance(1);
      skip_space();
      if (position_ >= text_.size() || (text_[position_] != '\'' && text_[position_] != '"'))
        fail("value of attribute " + a.name + " is not quoted");
      const char quote = text_[position_];
      advance(1);
      const size_t end = text_.find(quote, position_);
      if (end == std::string::npos) fail("value of attribute " + a.name + " is not terminated", a.line);
      const std::string raw = text_.substr(position_, end - position_);
      advance(end - position_ + 1);
      a.value = decoded(raw, a.line);
      e.attributes.push_back(std::move(a));
    }
    for (;;) {
      skip_misc();
      if (position_ >= text_.size()) fail("element <" + e.name + "> is never closed", e.line);
      if (at("</")) {
        advance(2);
        const int line = line_;
        const std::string closing = name_token();
        if (closing != e.name) fail("</" + closing + "> closes <" + e.name + "> of line " + std::to_string(e.line), line);
        skip_space();
        if (!at(">")) fail("expected '>' after </" + closing);
        advance(1);
        --depth_;
        return e;
      }
      e.children.push_back(element());
    }
  }

  const std::string& text_;
  const std::string& name_;
  size_t position_ = 0;
  int line_ = 1;
  int depth_ = 0;
};

// Elements to nodes: the X3D layer.
class X3dBuilder {
 public:
  explicit X3dBuilder(const XmlReader& reader) : reader_(reader) {}

  NodeDocument document(const XmlElement& root) {
    if (root.name != "X3D") reader_.fail("the root element is <" + root.name + ">, not <X3D>", root.line);
    NodeDocument document;
    document.dialect = VrmlDialect::x3d;
    for (const auto& child : root.children) {
      if (child.name == "head") continue;
      if (child.name != "Scene") reader_.fail("unexpected <" + child.name + "> in <X3D>", child.line);
      for (const auto& e : child.children) document.roots.push_back(node(e));
    }
    return document;
  }

 private:
  NodePtr node(const XmlElement& e) {
    if (const auto* use = e.attribute("USE")) {
      auto it = defs_.find(use->value);
      if (it == defs_.end()) reader_.fail("USE='" + use->value + "' before any DEF='" + use->value + "'", use->line);
      return it->second;
    }
    const NodeSchema* schema = node_schema(VrmlDialect::x3d, e.name);
    if (!schema) reader_.fail("unsupported node " + e.name + " (outside the X3D subset cadnurbs reads)", e.line);
    NodePtr node = make_node(e.name);
    node->line = e.line;
    for (const auto& a : e.attributes) {
      if (a.name == "DEF") {
        node->def_name = a.value;
        continue;
      }
      if (a.name == "containerField" || a.name == "class") continue;
      const auto type = field_type(*schema, a.name);
      if (!type) reader_.fail(e.name + " has no field " + a.name + " in the subset cadnurbs reads", a.line);
      if (*type == FieldType::SFNode || *type == FieldType::MFNode)
        reader_.fail("field " + a.name + " holds nodes; give it as a child element", a.line);
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
        reader_.fail(e.name + " has no node field " + container + " for <" + c.name + ">", c.line);
      Field* field = nullptr;
      for (auto& f : node->fields)
        if (f.name == container) field = &f;
      if (*type == FieldType::SFNode) {
        if (field) reader_.fail("field " + container + " of " + e.name + " is given twice", c.line);
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
        reader_.fail("field " + a.name + ": '" + s.substr(i, j - i) + "' is not a finite number", a.line);
      out.push_back(v);
      i = j;
    }
    if (out.size() % arity != 0)
      reader_.fail("field " + a.name + " has " + std::to_string(out.size()) + " numbers, not a multiple of " +
                       std::to_string(arity),
                   a.line);
    return out;
  }

  std::vector<double> exactly(const XmlAttribute& a, size_t count) const {
    auto v = numbers(a, 1);
    if (v.size() != count) reader_.fail("field " + a.name + " needs " + std::to_string(count) + " numbers", a.line);
    return v;
  }

  int integer(const XmlAttribute& a, double v) const {
    if (v != static_cast<double>(static_cast<int>(v))) reader_.fail("field " + a.name + ": expected integers", a.line);
    return static_cast<int>(v);
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
      if (s[i] != '"') reader_.fail("field " + a.name + ": expected a quoted string", a.line);
      std::string value;
      size_t j = i + 1;
      for (; j < s.size() && s[j] != '"'; ++j) {
        if (s[j] == '\\' && j + 1 < s.size()) ++j;
        value.push_back(s[j]);
      }
      if (j >= s.size()) reader_.fail("field " + a.name + ": string is not terminated", a.line);
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
        reader_.fail("field " + a.name + ": expected true or false", a.line);
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
    reader_.fail("field " + a.name + " cannot be an attribute", a.line);
  }

  const XmlReader& reader_;
  std::map<std::string, NodePtr> defs_;
};

}  // namespace

NodeDocument parse_xml(const std::string& text, const std::string& name_for_errors) {
  XmlReader reader(text, name_for_errors);
  const XmlElement root = reader.document();
  return X3dBuilder(reader).document(root);
}

}  // namespace cadnurbs
