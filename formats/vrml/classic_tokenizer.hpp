#pragma once
// Tokens of the classic VRML97/X3D encoding: words, numbers, strings and the four brackets. Comments
// ('#' to the end of the line) and commas are whitespace.
#include <string>
#include <string_view>

namespace cadnurbs {

struct ClassicToken {
  enum class Kind { word, number, string, open_bracket, close_bracket, open_brace, close_brace, end };
  Kind kind = Kind::end;
  std::string text;  // a string's text is unescaped
  int line = 0;
  size_t begin = 0, end = 0;  // the token's bytes in the text, [begin, end): for rewriting a text in place
};

class ClassicTokenizer {
 public:
  // `text` must outlive the tokenizer.
  explicit ClassicTokenizer(std::string_view text) : text_(text) {}

  // The next token (Kind::end at the end of the text); consumes it. Throws std::runtime_error
  // "line N: <reason>" for an unterminated string.
  ClassicToken next();

  // The next token without consuming it.
  const ClassicToken& peek();

 private:
  ClassicToken scan();

  std::string_view text_;
  size_t position_ = 0;
  int line_ = 1;
  bool has_peeked_ = false;
  ClassicToken peeked_;
};

}  // namespace cadnurbs
