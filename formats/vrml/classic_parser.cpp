#include "formats/vrml/classic_parser.hpp"

#include <charconv>
#include <cmath>
#include <map>
#include <optional>
#include <tuple>
#include <stdexcept>

#include "core/chars_to_double.hpp"
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
    document_.dialect = header();
    dialect_ = document_.dialect;
    for (;;) {
      const ClassicToken& token = peek();
      if (token.kind == Kind::end) break;
      if (token.kind == Kind::word && statement(token.text)) continue;
      document_.roots.push_back(node_statement());
    }
    return std::move(document_);
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

  // Header statements are skipped; PROTO / EXTERNPROTO interfaces, ROUTE, IMPORT and EXPORT are
  // recorded; UNIT is refused (it would change what the numbers mean). False: not a statement.
  bool statement(const std::string& word) {
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
    if (word == "EXTERNPROTO" || word == "PROTO") {
      proto_declaration(word == "EXTERNPROTO");
      return true;
    }
    if (word == "ROUTE") {
      route();
      return true;
    }
    if (word == "IMPORT" || word == "EXPORT") {
      import_export(word);
      return true;
    }
    if (word == "UNIT") fail(peek().line, "UNIT statements are not read: they change the units of the numbers");
    return false;
  }

  // "a.b" as its two names.
  std::pair<std::string, std::string> dotted(const std::string& what) {
    const ClassicToken token = expect(Kind::word, what);
    const size_t dot = token.text.find('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == token.text.size())
      fail(token.line, "expected " + what + " as NAME.FIELD, found '" + token.text + "'");
    return {token.text.substr(0, dot), token.text.substr(dot + 1)};
  }

  void route() {
    const int line = next().line;
    Route r;
    std::tie(r.from_node, r.from_field) = dotted("a ROUTE's source");
    const ClassicToken to = expect(Kind::word, "TO");
    if (to.text != "TO") fail(to.line, "expected TO in a ROUTE, found '" + to.text + "'");
    std::tie(r.to_node, r.to_field) = dotted("a ROUTE's destination");
    r.line = line;
    document_.routes.push_back(std::move(r));
  }

  // IMPORT inline.name [AS name] / EXPORT name [AS name].
  void import_export(const std::string& word) {
    next();
    ImportExport statement;
    statement.import = word == "IMPORT";
    if (statement.import) std::tie(statement.inline_def, statement.name) = dotted("an IMPORT's Inline.name");
    else statement.name = expect(Kind::word, "a name after EXPORT").text;
    if (peek().kind == Kind::word && peek().text == "AS") {
      next();
      statement.as = expect(Kind::word, "a name after AS").text;
    }
    document_.imports_exports.push_back(std::move(statement));
  }

  // "IS <proto field>" in a PROTO body, instead of a value: the proto field's name, else nothing.
  std::optional<std::string> is_connection() {
    if (!(peek().kind == Kind::word && peek().text == "IS")) return std::nullopt;
    const ClassicToken is = next();
    if (body_depth_ == 0) fail(is.line, "IS outside a PROTO body");
    return expect(Kind::word, "a PROTO field after IS").text;
  }

  // An interface declaration "<access> <Type> <name>" whose access keyword has been read, with the value a
  // PROTO's field or exposedField (or a Script's) has, or an IS connection in a PROTO body.
  FieldSchema declaration(const ClassicToken& keyword, bool with_value, InterfaceDeclaration& out,
                          std::optional<std::string>& is) {
    const auto access = declaration_access(keyword.text);
    if (!access) fail(keyword.line, "expected field, exposedField, eventIn or eventOut, found '" + keyword.text + "'");
    const ClassicToken type = expect(Kind::word, "a field type");
    const ClassicToken name = expect(Kind::word, "a field name");
    auto schema = declared_field(name.text, type.text, *access);
    if (!schema) fail(type.line, "'" + type.text + "' is not a field type");
    out = InterfaceDeclaration{keyword.text, type.text, name.text, std::nullopt};
    is = is_connection();
    if (!is && with_value && (*access == FieldAccess::initialize_only || *access == FieldAccess::input_output))
      out.default_value = value(*schema, name);
    return *schema;
  }

  void proto_declaration(bool external) {
    next();
    const ClassicToken name = expect(Kind::word, external ? "an EXTERNPROTO name" : "a PROTO name");
    ProtoDeclaration proto{name.text, external, {}, {}, nullptr, name.line};
    NodeSchema schema{name.text, "children", {}};
    expect(Kind::open_bracket, "'[' after " + name.text);
    // A PROTO's defaults and body are in its own DEF name scope.
    auto outer_defs = std::move(defs_);
    defs_.clear();
    while (peek().kind != Kind::close_bracket) {
      if (peek().kind == Kind::end) fail(name.line, "the interface of " + name.text + " is never closed");
      InterfaceDeclaration d;
      std::optional<std::string> is;
      schema.fields.push_back(declaration(expect(Kind::word, "a field declaration"), !external, d, is));
      if (is) fail(name.line, "IS in the interface of " + name.text);
      proto.interface.push_back(std::move(d));
    }
    next();
    if (external) {
      if (peek().kind == Kind::string) {
        proto.urls.push_back(next().text);
      } else {
        expect(Kind::open_bracket, "the URLs of " + name.text);
        while (peek().kind != Kind::close_bracket) proto.urls.push_back(expect(Kind::string, "a URL").text);
        next();
      }
    } else {
      // The PROTO is known inside its own body (a body may nest an instance of it only through a
      // field, which VRML forbids; knowing it costs nothing).
      proto_schemas_[name.text] = schema;
      proto.body = std::make_shared<NodeDocument>(body(name));
    }
    defs_ = std::move(outer_defs);
    proto_schemas_[name.text] = std::move(schema);
    document_.protos.push_back(std::move(proto));
  }

  // A PROTO body: "{ statements }", its PROTOs local to it.
  NodeDocument body(const ClassicToken& name) {
    expect(Kind::open_brace, "'{' for the body of " + name.text);
    NodeDocument outer = std::move(document_);
    document_ = NodeDocument{};
    document_.dialect = dialect_;
    const auto outer_protos = proto_schemas_;
    ++body_depth_;
    for (;;) {
      const ClassicToken& token = peek();
      if (token.kind == Kind::close_brace) break;
      if (token.kind == Kind::end) fail(name.line, "the body of " + name.text + " is never closed");
      if (token.kind == Kind::word && statement(token.text)) continue;
      document_.roots.push_back(node_statement());
    }
    next();
    --body_depth_;
    proto_schemas_ = outer_protos;
    NodeDocument out = std::move(document_);
    document_ = std::move(outer);
    return out;
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
    const auto proto = proto_schemas_.find(token.text);
    const NodeSchema* proto_schema = proto == proto_schemas_.end() ? nullptr : &proto->second;
    if (!schema && !proto_schema)
      fail(token.line, "unknown node " + token.text + " (neither a " +
                           (dialect_ == VrmlDialect::vrml97 ? "VRML97" : "X3D") + " node nor a PROTO declared before it)");
    NodePtr node = make_node(token.text, def_name);
    node->line = token.line;
    node->proto_instance = !schema;
    if (++depth_ > max_depth) fail(token.line, "nodes nested deeper than " + std::to_string(max_depth) + " levels");
    expect(Kind::open_brace, "'{' after " + token.text);
    std::vector<FieldSchema> declared;  // a Script's own fields
    for (;;) {
      const ClassicToken field_name = next();
      if (field_name.kind == Kind::close_brace) break;
      if (field_name.kind != Kind::word)
        fail(field_name.line, "expected a field of " + node->type + " or '}', found " + describe(field_name));
      if (declaration_access(field_name.text) && declares_own_fields(node->type)) {
        InterfaceDeclaration d;
        std::optional<std::string> is;
        declared.push_back(declaration(field_name, true, d, is));
        if (is) node->is_connections.push_back(IsConnection{d.name, *is});
        if (d.default_value)
          node->fields.push_back(Field{d.name, std::move(*d.default_value), {}, field_name.line});
        d.default_value.reset();
        node->declarations.push_back(std::move(d));
        continue;
      }
      const FieldSchema* f = schema ? find_field(*schema, field_name.text) : nullptr;
      if (!f && proto_schema) f = find_field(*proto_schema, field_name.text);
      if (!f)
        for (const auto& d : declared)
          if (d.name == field_name.text) f = &d;
      if (!f) fail(field_name.line, node->type + " has no field " + field_name.text);
      if ((f->access == FieldAccess::input_only || f->access == FieldAccess::output_only) &&
          !(peek().kind == Kind::word && peek().text == "IS"))
        fail(field_name.line, "field " + field_name.text + " of " + node->type + " is an event: it has no value");
      if (auto is = is_connection()) {
        node->is_connections.push_back(IsConnection{field_name.text, *is});
        continue;
      }
      if (node->find(field_name.text)) fail(field_name.line, "field " + field_name.text + " is given twice");
      Field field{field_name.text, value(*f, field_name), {}, field_name.line};
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
    const auto result = chars_to_double(first, last, value);
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


  // Puts back a token just read (a declaration keyword): the declaration reader starts from it.

  // One word of a FieldWords value: a number or TRUE/FALSE.
  std::string word(const ClassicToken& field) {
    const ClassicToken token = next();
    if (token.kind == Kind::number || (token.kind == Kind::word && (token.text == "TRUE" || token.text == "FALSE")))
      return token.text;
    fail(token.line, "field " + field.text + ": expected a number or TRUE/FALSE, found " + describe(token));
  }

  // One value of `type_name` as words (an SFImage: width, height, components, then a pixel per
  // width x height).
  void words_of_one(const std::string& type_name, const ClassicToken& field, std::vector<std::string>& out) {
    int count = words_per_value(type_name);
    if (count == 0) {
      double size[3];
      for (double& v : size) {
        out.push_back(word(field));
        v = std::strtod(out.back().c_str(), nullptr);
      }
      if (!(size[0] >= 0 && size[1] >= 0 && size[0] * size[1] <= 1e8)) fail(field.line, "field " + field.text + ": image size out of range");
      count = static_cast<int>(size[0] * size[1]);
    }
    for (int i = 0; i < count; ++i) out.push_back(word(field));
  }

  FieldWords words(const FieldSchema& schema, const ClassicToken& field) {
    FieldWords out{schema.type_name, {}};
    if (schema.type == FieldType::MFWords && peek().kind == Kind::open_bracket) {
      next();
      while (peek().kind != Kind::close_bracket) {
        if (peek().kind == Kind::end) fail(field.line, "field " + field.text + ": '[' is never closed");
        words_of_one(schema.type_name, field, out.words);
      }
      next();
    } else {
      words_of_one(schema.type_name, field, out.words);
    }
    return out;
  }

  FieldValue value(const FieldSchema& schema, const ClassicToken& field) {
    if (schema.type == FieldType::SFWords || schema.type == FieldType::MFWords) return words(schema, field);
    switch (schema.type) {
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
      case FieldType::SFWords:
      case FieldType::MFWords: break;
      case FieldType::SFNode: {
        if (peek().kind == Kind::word && peek().text == "NULL") {
          next();
          return SFNode{};
        }
        return SFNode{node_statement()};
      }
      case FieldType::MFNode: {
        MFNode out;
        if (peek().kind == Kind::word && peek().text == "NULL") {  // lenient: some writers say NULL for []
          next();
          return out;
        }
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
  NodeDocument document_;
  std::map<std::string, NodeSchema> proto_schemas_;
  int body_depth_ = 0;  // inside PROTO bodies: IS is allowed
  // Recursion guard: far deeper than any real scene, far shallower than the stack.
  static constexpr int max_depth = 1000;
  int depth_ = 0;
};

}  // namespace

NodeDocument parse_classic(const std::string& text, const std::string& name_for_errors) {
  return ClassicParser(text, name_for_errors).parse();
}

}  // namespace cadnurbs
