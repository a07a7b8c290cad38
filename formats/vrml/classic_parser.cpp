#include "formats/vrml/classic_parser.hpp"

#include <charconv>
#include <cmath>
#include <map>
#include <stdexcept>

#include "formats/common/file_io.hpp"
#include "formats/vrml/parse_error.hpp"
#include "formats/vrml/classic_tokenizer.hpp"
#include "formats/vrml/field_integer.hpp"
#include "formats/vrml/node_schema.hpp"

namespace cadnurbs {

namespace {

using Kind = ClassicToken::Kind;

class ClassicParser {
 public:
  ClassicParser(const std::string& text, const std::string& name) : text_(text), name_(name), tokens_(text) {}

  NodeDocument parse() {
    NodeDocument document;
    document.dialect = header();
    dialect_ = document.dialect;
    for (;;) {
      const ClassicToken& token = peek();
      if (token.kind == Kind::end) break;
      if (token.kind == Kind::word && skip_statement(token.text)) continue;
      document.roots.push_back(node_statement());
    }
    return document;
  }

 private:
  [[noreturn]] void fail(int line, const std::string& reason) const {
    throw_parse_error(name_, line, reason);
  }

  const ClassicToken& peek() {
    try {
      return tokens_.peek();
    } catch (const std::runtime_error& e) {
      throw FileError(name_ + ": " + e.what());
    }
  }

  ClassicToken next() {
    try {
      return tokens_.next();
    } catch (const std::runtime_error& e) {
      throw FileError(name_ + ": " + e.what());
    }
  }

  ClassicToken expect(Kind kind, const std::string& what) {
    ClassicToken token = next();
    if (token.kind != kind) fail(token.line, "expected " + what + ", found " + describe(token));
    return token;
  }

  static std::string describe(const ClassicToken& token) {
    switch (token.kind) {
      case Kind::end: return "the end of the file";
      case Kind::string: return "a string";
      case Kind::open_bracket: return "'['";
      case Kind::close_bracket: return "']'";
      case Kind::open_brace: return "'{'";
      case Kind::close_brace: return "'}'";
      default: return "'" + token.text + "'";
    }
  }

  VrmlDialect header() {
    const std::string first_line = text_.substr(0, text_.find('\n'));
    auto starts = [&](const char* prefix) { return first_line.rfind(prefix, 0) == 0; };
    if (starts("#VRML V2.0 utf8")) return VrmlDialect::vrml97;
    if (starts("#X3D V3.") || starts("#X3D V4.")) return VrmlDialect::x3d;
    fail(1, "not a VRML97 (#VRML V2.0 utf8) or X3D classic (#X3D V3.x utf8) header");
  }

  // Header statements are skipped; the ones outside the subset are refused. False: not a statement.
  bool skip_statement(const std::string& word) {
    if (word == "PROFILE") {
      next();
      expect(Kind::word, "a profile name");
      return true;
    }
    if (word == "COMPONENT") {
      next();
      expect(Kind::word, "a component name:level");
      return true;
    }
    if (word == "META") {
      next();
      expect(Kind::string, "a META name");
      expect(Kind::string, "a META value");
      return true;
    }
    if (word == "EXTERNPROTO") {
      next();
      expect(Kind::word, "an EXTERNPROTO name");
      skip_balanced(Kind::open_bracket, Kind::close_bracket);
      if (peek().kind == Kind::string) next();
      else skip_balanced(Kind::open_bracket, Kind::close_bracket);
      return true;
    }
    if (word == "PROTO") {
      next();
      expect(Kind::word, "a PROTO name");
      skip_balanced(Kind::open_bracket, Kind::close_bracket);
      skip_balanced(Kind::open_brace, Kind::close_brace);
      return true;
    }
    if (word == "ROUTE" || word == "IMPORT" || word == "EXPORT" || word == "UNIT")
      fail(peek().line, word + " statements are outside the subset cadnurbs reads");
    return false;
  }

  void skip_balanced(Kind open, Kind close) {
    const ClassicToken first = expect(open, open == Kind::open_bracket ? "'['" : "'{'");
    for (int depth = 1; depth > 0;) {
      const ClassicToken token = next();
      if (token.kind == Kind::end) fail(first.line, "unterminated declaration");
      if (token.kind == open) ++depth;
      if (token.kind == close) --depth;
    }
  }

  NodePtr node_statement() {
    ClassicToken token = next();
    if (token.kind != Kind::word) fail(token.line, "expected a node, found " + describe(token));
    if (token.text == "USE") {
      const ClassicToken name = expect(Kind::word, "a name after USE");
      auto it = defs_.find(name.text);
      if (it == defs_.end()) fail(name.line, "USE " + name.text + " before any DEF " + name.text);
      return it->second;
    }
    std::string def_name;
    if (token.text == "DEF") {
      def_name = expect(Kind::word, "a name after DEF").text;
      token = expect(Kind::word, "a node type after DEF " + def_name);
    }
    const NodeSchema* schema = node_schema(dialect_, token.text);
    if (!schema)
      fail(token.line, "unsupported node " + token.text + " (outside the " +
                           (dialect_ == VrmlDialect::vrml97 ? "VRML97" : "X3D") + " subset cadnurbs reads)");
    NodePtr node = make_node(token.text, def_name);
    node->line = token.line;
    if (++depth_ > max_depth) fail(token.line, "nodes nested deeper than " + std::to_string(max_depth) + " levels");
    expect(Kind::open_brace, "'{' after " + token.text);
    for (;;) {
      const ClassicToken field_name = next();
      if (field_name.kind == Kind::close_brace) break;
      if (field_name.kind != Kind::word)
        fail(field_name.line, "expected a field of " + node->type + " or '}', found " + describe(field_name));
      const auto type = field_type(*schema, field_name.text);
      if (!type) fail(field_name.line, node->type + " has no field " + field_name.text + " in the subset cadnurbs reads");
      if (node->find(field_name.text)) fail(field_name.line, "field " + field_name.text + " is given twice");
      Field field{field_name.text, value(*type, field_name), {}, field_name.line};
      node->fields.push_back(std::move(field));
    }
    --depth_;
    // Known to USE only after its body: a node cannot contain itself.
    if (!def_name.empty()) defs_[def_name] = node;
    return node;
  }

  double number(const ClassicToken& field) {
    const ClassicToken token = next();
    if (token.kind != Kind::number) fail(token.line, "field " + field.text + ": expected a number, found " + describe(token));
    const char* first = token.text.data();
    const char* last = first + token.text.size();
    if (*first == '+') ++first;
    double value = 0.0;
    const auto result = std::from_chars(first, last, value);
    if (result.ec == std::errc() && result.ptr == last) {
      if (!std::isfinite(value)) fail(token.line, "field " + field.text + ": '" + token.text + "' is not a finite number");
      return value;
    }
    if (result.ec == std::errc::result_out_of_range && result.ptr == last)
      fail(token.line, "field " + field.text + ": '" + token.text + "' is out of the range of double");
    // Hexadecimal integers (0x1F) are legal VRML too.
    const bool negative = *first == '-';
    const char* digits = first + (negative ? 1 : 0);
    if (last - digits > 2 && digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X')) {
      long hex = 0;
      const auto r = std::from_chars(digits + 2, last, hex, 16);
      if (r.ec == std::errc() && r.ptr == last) return static_cast<double>(negative ? -hex : hex);
    }
    fail(token.line, "field " + field.text + ": '" + token.text + "' is not a number");
  }

  int integer(const ClassicToken& field) {
    const int line = peek().line;
    const std::optional<int> value = field_integer(number(field));
    if (!value) fail(line, "field " + field.text + ": expected an integer");
    return *value;
  }

  // Numbers of an MF field: "[ ... ]" or a single value of `arity` numbers.
  std::vector<double> numbers(const ClassicToken& field, size_t arity) {
    std::vector<double> out;
    if (peek().kind == Kind::open_bracket) {
      next();
      while (peek().kind != Kind::close_bracket) {
        if (peek().kind == Kind::end) fail(field.line, "field " + field.text + ": '[' is never closed");
        out.push_back(number(field));
      }
      next();
    } else {
      for (size_t i = 0; i < arity; ++i) out.push_back(number(field));
    }
    if (out.size() % arity != 0)
      fail(field.line, "field " + field.text + " has " + std::to_string(out.size()) + " numbers, not a multiple of " +
                           std::to_string(arity));
    return out;
  }

  Eigen::Vector3d vector3(const ClassicToken& field) {
    Eigen::Vector3d v;
    for (int k = 0; k < 3; ++k) v[k] = number(field);
    return v;
  }

  std::string string_value(const ClassicToken& field) {
    const ClassicToken token = next();
    if (token.kind != Kind::string) fail(token.line, "field " + field.text + ": expected a string, found " + describe(token));
    return token.text;
  }

  FieldValue value(FieldType type, const ClassicToken& field) {
    switch (type) {
      case FieldType::SFBool: {
        const ClassicToken token = next();
        if (token.kind == Kind::word && token.text == "TRUE") return true;
        if (token.kind == Kind::word && token.text == "FALSE") return false;
        fail(token.line, "field " + field.text + ": expected TRUE or FALSE, found " + describe(token));
      }
      case FieldType::SFInt32: return integer(field);
      case FieldType::SFFloat: return number(field);
      case FieldType::SFString: return string_value(field);
      case FieldType::MFFloat: return MFFloat{numbers(field, 1)};
      case FieldType::MFInt32: {
        MFInt32 out;
        for (double v : numbers(field, 1)) {
          const std::optional<int> value = field_integer(v);
          if (!value) fail(field.line, "field " + field.text + ": expected integers");
          out.values.push_back(*value);
        }
        return out;
      }
      case FieldType::MFVec2f: {
        const auto v = numbers(field, 2);
        MFVec2f out;
        for (size_t i = 0; i < v.size(); i += 2) out.values.emplace_back(v[i], v[i + 1]);
        return out;
      }
      case FieldType::MFVec3f: {
        const auto v = numbers(field, 3);
        MFVec3f out;
        for (size_t i = 0; i < v.size(); i += 3) out.values.emplace_back(v[i], v[i + 1], v[i + 2]);
        return out;
      }
      case FieldType::MFString: {
        MFString out;
        if (peek().kind != Kind::open_bracket) {
          out.values.push_back(string_value(field));
          return out;
        }
        next();
        while (peek().kind != Kind::close_bracket) out.values.push_back(string_value(field));
        next();
        return out;
      }
      case FieldType::SFColor: return SFColor{vector3(field)};
      case FieldType::SFVec3f: return SFVec3f{vector3(field)};
      case FieldType::SFRotation: {
        SFRotation r;
        r.axis = vector3(field);
        r.angle = number(field);
        return r;
      }
      case FieldType::SFNode: {
        if (peek().kind == Kind::word && peek().text == "NULL") {
          next();
          return SFNode{};
        }
        return SFNode{node_statement()};
      }
      case FieldType::MFNode: {
        MFNode out;
        if (peek().kind != Kind::open_bracket) {
          out.nodes.push_back(node_statement());
          return out;
        }
        next();
        while (peek().kind != Kind::close_bracket) {
          if (peek().kind == Kind::end) fail(field.line, "field " + field.text + ": '[' is never closed");
          out.nodes.push_back(node_statement());
        }
        next();
        return out;
      }
    }
    fail(field.line, "field " + field.text + " has an unknown type");
  }

  const std::string& text_;
  const std::string& name_;
  ClassicTokenizer tokens_;
  VrmlDialect dialect_ = VrmlDialect::x3d;
  std::map<std::string, NodePtr> defs_;
  // Recursion guard: far deeper than any real scene, far shallower than the stack.
  static constexpr int max_depth = 1000;
  int depth_ = 0;
};

}  // namespace

NodeDocument parse_classic(const std::string& text, const std::string& name_for_errors) {
  return ClassicParser(text, name_for_errors).parse();
}

}  // namespace cadnurbs
