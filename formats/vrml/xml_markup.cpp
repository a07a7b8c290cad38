#include "formats/vrml/xml_markup.hpp"

#include <cctype>
#include <charconv>

#include "formats/vrml/parse_error.hpp"

namespace cadnurbs {

const XmlAttribute* XmlElement::attribute(const std::string& n) const {
  for (const auto& a : attributes)
    if (a.name == n) return &a;
  return nullptr;
}

namespace {

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

 private:
  [[noreturn]] void fail(const std::string& reason, int line = 0) const {
    throw_parse_error(name_, line ? line : line_, reason);
  }

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

  // Declarations, processing instructions, comments, DOCTYPE and text between elements; the text of
  // CDATA sections is appended to `cdata` when given.
  void skip_misc(std::string* cdata = nullptr) {
    for (;;) {
      skip_space();
      if (at("<?")) {
        skip_to("?>", "processing instruction");
      } else if (at("<!--")) {
        skip_to("-->", "comment");
      } else if (at("<![CDATA[")) {
        const size_t start = position_ + 9;
        skip_to("]]>", "CDATA section");
        if (cdata) cdata->append(text_, start, position_ - 3 - start);
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
    e.begin = position_;
    // Recursion guard: far deeper than any real scene, far shallower than the stack.
    if (++depth_ > 1000) fail("elements nested deeper than 1000 levels");
    advance(1);  // '<'
    e.name = name_token();
    for (;;) {
      skip_space();
      if (position_ >= text_.size()) fail("element <" + e.name + "> is not terminated", e.line);
      if (at("/>")) {
        advance(2);
        e.end = position_;
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
      skip_misc(&e.cdata);
      if (position_ >= text_.size()) fail("element <" + e.name + "> is never closed", e.line);
      if (at("</")) {
        advance(2);
        const int line = line_;
        const std::string closing = name_token();
        if (closing != e.name) fail("</" + closing + "> closes <" + e.name + "> of line " + std::to_string(e.line), line);
        skip_space();
        if (!at(">")) fail("expected '>' after </" + closing);
        advance(1);
        e.end = position_;
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

}  // namespace

XmlElement parse_xml_markup(const std::string& text, const std::string& name_for_errors) {
  return XmlReader(text, name_for_errors).document();
}

}  // namespace cadnurbs
