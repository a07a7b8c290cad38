#include "formats/vrml/classic_tokenizer.hpp"

#include <stdexcept>

namespace cadnurbs {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == ','; }

bool ends_word(char c) {
  return is_space(c) || c == '#' || c == '"' || c == '\'' || c == '[' || c == ']' || c == '{' || c == '}' ||
         c == '\\' || static_cast<unsigned char>(c) < 0x20;
}

}  // namespace

ClassicToken ClassicTokenizer::next() {
  if (has_peeked_) {
    has_peeked_ = false;
    return std::move(peeked_);
  }
  return scan();
}

const ClassicToken& ClassicTokenizer::peek() {
  if (!has_peeked_) {
    peeked_ = scan();
    has_peeked_ = true;
  }
  return peeked_;
}

ClassicToken ClassicTokenizer::scan() {
  using Kind = ClassicToken::Kind;
  // Whitespace, commas and comments.
  while (position_ < text_.size()) {
    const char c = text_[position_];
    if (c == '\n') {
      ++line_;
      ++position_;
    } else if (is_space(c)) {
      ++position_;
    } else if (c == '#') {
      while (position_ < text_.size() && text_[position_] != '\n') ++position_;
    } else {
      break;
    }
  }
  ClassicToken token;
  token.line = line_;
  token.begin = token.end = position_;
  if (position_ >= text_.size()) return token;
  token.end = position_ + 1;
  const char c = text_[position_];
  switch (c) {
    case '[': token.kind = Kind::open_bracket; ++position_; return token;
    case ']': token.kind = Kind::close_bracket; ++position_; return token;
    case '{': token.kind = Kind::open_brace; ++position_; return token;
    case '}': token.kind = Kind::close_brace; ++position_; return token;
    default: break;
  }
  if (c == '"') {
    token.kind = Kind::string;
    ++position_;
    while (true) {
      if (position_ >= text_.size())
        throw std::runtime_error("line " + std::to_string(token.line) + ": string is not terminated");
      const char s = text_[position_++];
      if (s == '"') break;
      if (s == '\\' && position_ < text_.size()) {
        token.text.push_back(text_[position_++]);
        continue;
      }
      if (s == '\n') ++line_;
      token.text.push_back(s);
    }
    token.end = position_;
    return token;
  }
  const size_t start = position_;
  while (position_ < text_.size() && !ends_word(text_[position_])) ++position_;
  if (position_ == start) ++position_;  // a lone stray character (quote, backslash) becomes a word
  token.text = std::string(text_.substr(start, position_ - start));
  token.end = position_;
  const bool numeric = (c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.';
  token.kind = numeric ? Kind::number : Kind::word;
  return token;
}

}  // namespace cadnurbs
