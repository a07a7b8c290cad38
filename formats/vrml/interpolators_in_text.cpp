#include "formats/vrml/interpolators_in_text.hpp"

#include <charconv>
#include <functional>

#include "core/chars_to_double.hpp"
#include "formats/vrml/classic_tokenizer.hpp"
#include "formats/vrml/parse_error.hpp"
#include "formats/vrml/xml_markup.hpp"

namespace cadnurbs {

namespace {

using Kind = ClassicToken::Kind;

bool is_interpolator_type(const std::string& name) {
  return name == "PositionInterpolator" || name == "OrientationInterpolator";
}

// A number's text (VRML allows a leading '+'), or false.
bool parse_number(std::string_view text, double& value) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  const auto r = chars_to_double(text.data(), text.data() + text.size(), value);
  return r.ec == std::errc() && r.ptr == text.data() + text.size();
}

class ClassicInterpolators {
 public:
  ClassicInterpolators(const std::string& text, const std::string& name) : tokens_(text), name_(name) {}

  std::vector<InterpolatorInText> all() {
    std::vector<InterpolatorInText> found;
    ClassicToken before_previous, previous;  // the two tokens before `token`, for "DEF name"
    for (;;) {
      ClassicToken token = next();
      if (token.kind == Kind::end) return found;
      if (token.kind == Kind::word && is_interpolator_type(token.text) && peek().kind == Kind::open_brace) {
        InterpolatorInText node;
        node.type = token.text;
        node.line = token.line;
        node.begin = token.begin;
        if (previous.kind == Kind::word && before_previous.kind == Kind::word && before_previous.text == "DEF") {
          node.def_name = previous.text;
          node.begin = before_previous.begin;
        }
        next();  // '{'
        read_fields(node);
        found.push_back(std::move(node));
        before_previous = previous = ClassicToken();
        continue;
      }
      before_previous = std::move(previous);
      previous = std::move(token);
    }
  }

 private:
  ClassicToken next() {
    try {
      return tokens_.next();
    } catch (const std::runtime_error& e) {  // the tokenizer's "line N: reason"
      throw FileError(name_ + ": " + e.what());
    }
  }

  const ClassicToken& peek() {
    try {
      return tokens_.peek();
    } catch (const std::runtime_error& e) {
      throw FileError(name_ + ": " + e.what());
    }
  }

  [[noreturn]] void fail(int line, const std::string& reason) { throw_parse_error(name_, line, reason); }

  void read_fields(InterpolatorInText& node) {
    for (;;) {
      const ClassicToken field = next();
      if (field.kind == Kind::close_brace) {
        node.end = field.end;
        return;
      }
      if (field.kind != Kind::word) fail(field.line, node.type + " is not closed where a field name should be");
      if (peek().kind == Kind::word && peek().text == "IS") {
        next();
        next();
        if (node.unconvertible.empty()) node.unconvertible = "its field " + field.text + " is given by IS";
      } else if (field.text == "key" || field.text == "keyValue") {
        numbers(field, field.text == "key" ? node.key : node.key_value);
      } else {
        if (node.unconvertible.empty()) node.unconvertible = "it has a field " + field.text;
        skip_value();
      }
    }
  }

  // An MF value in brackets, or a single value without them (one tuple: its numbers up to the next word).
  void numbers(const ClassicToken& field, std::vector<double>& out) {
    const auto number = [&](const ClassicToken& token) {
      double value = 0;
      if (token.kind != Kind::number || !parse_number(token.text, value))
        fail(token.line, field.text + " holds '" + token.text + "', not a number");
      out.push_back(value);
    };
    if (peek().kind != Kind::open_bracket) {
      do number(next());
      while (peek().kind == Kind::number);
      return;
    }
    next();
    for (;;) {
      const ClassicToken token = next();
      if (token.kind == Kind::close_bracket) return;
      if (token.kind == Kind::end) fail(field.line, field.text + "'s '[' is never closed");
      number(token);
    }
  }

  // Any field value: numbers, strings, TRUE/FALSE/NULL, a bracketed list, a node (DEF'd or not), a USE.
  void skip_value() {
    const ClassicToken& first = peek();
    if (first.kind == Kind::open_bracket) return skip_balanced();
    if (first.kind == Kind::word) {
      const ClassicToken word = next();
      if (word.text == "USE") return static_cast<void>(next());
      if (word.text == "DEF") next(), next();
      if (word.text == "TRUE" || word.text == "FALSE" || word.text == "NULL") return;
      if (peek().kind == Kind::open_brace) skip_balanced();
      return;
    }
    while (peek().kind == Kind::number || peek().kind == Kind::string) next();
  }

  void skip_balanced() {
    int depth = 0;
    do {
      const ClassicToken token = next();
      if (token.kind == Kind::end) fail(token.line, "a bracket or brace is never closed");
      if (token.kind == Kind::open_bracket || token.kind == Kind::open_brace) ++depth;
      if (token.kind == Kind::close_bracket || token.kind == Kind::close_brace) --depth;
    } while (depth > 0);
  }

  ClassicTokenizer tokens_;
  const std::string& name_;
};

std::vector<double> attribute_numbers(const XmlAttribute& attribute, const std::string& name) {
  std::vector<double> out;
  const std::string& text = attribute.value;
  size_t i = 0;
  const auto separator = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == ','; };
  while (i < text.size()) {
    while (i < text.size() && separator(text[i])) ++i;
    if (i == text.size()) break;
    size_t j = i;
    while (j < text.size() && !separator(text[j])) ++j;
    double value = 0;
    if (!parse_number(std::string_view(text).substr(i, j - i), value))
      throw_parse_error(name, attribute.line, attribute.name + " holds '" + text.substr(i, j - i) + "', not a number");
    out.push_back(value);
    i = j;
  }
  return out;
}

std::vector<InterpolatorInText> xml_interpolators(const std::string& text, const std::string& name) {
  std::vector<InterpolatorInText> found;
  const std::function<void(const XmlElement&)> visit = [&](const XmlElement& element) {
    if (!is_interpolator_type(element.name)) {
      for (const XmlElement& child : element.children) visit(child);
      return;
    }
    InterpolatorInText node;
    node.type = element.name;
    node.line = element.line;
    node.begin = element.begin;
    node.end = element.end;
    for (const XmlAttribute& a : element.attributes) {
      if (a.name == "DEF") node.def_name = a.value;
      else if (a.name == "containerField") node.container_field = a.value;
      else if (a.name == "key") node.key = attribute_numbers(a, name);
      else if (a.name == "keyValue") node.key_value = attribute_numbers(a, name);
      else if (a.name == "USE") node.use_name = a.value;
      else if (node.unconvertible.empty()) node.unconvertible = "it has an attribute " + a.name;
    }
    if (!element.children.empty() && node.unconvertible.empty())
      node.unconvertible = "it has a child element <" + element.children.front().name + ">";
    found.push_back(std::move(node));
  };
  visit(parse_xml_markup(text, name));
  return found;
}

}  // namespace

std::vector<InterpolatorInText> find_interpolators(const std::string& text, bool xml,
                                                   const std::string& name_for_errors) {
  if (xml) return xml_interpolators(text, name_for_errors);
  return ClassicInterpolators(text, name_for_errors).all();
}

}  // namespace cadnurbs
