#include "formats/step/step_precheck.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <unordered_set>
#include <vector>

#include "formats/common/file_io.hpp"

namespace cadnurbs {

namespace {

// OCCT stores integers and entity numbers as Standard_Integer (int).
constexpr std::int64_t largest_int = std::numeric_limits<std::int32_t>::max();

bool is_letter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_keyword_char(char c) { return is_letter(c) || is_digit(c) || c == '-'; }

bool equals_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const char x = (a[k] >= 'A' && a[k] <= 'Z') ? static_cast<char>(a[k] - 'A' + 'a') : a[k];
    if (x != b[k]) return false;
  }
  return true;
}

bool names_non_finite(std::string_view word) {
  return equals_ignoring_case(word, "inf") || equals_ignoring_case(word, "infinity") || equals_ignoring_case(word, "nan");
}

// A token as quoted in a message, cut at 40 characters.
std::string quoted(std::string_view token) {
  if (token.size() <= 40) return "'" + std::string(token) + "'";
  return "'" + std::string(token.substr(0, 40)) + "...' (" + std::to_string(token.size()) + " characters)";
}

struct Reference {
  std::int64_t target;
  long line;
  std::int64_t entity;
  std::string_view type;
};

class StepScanner {
 public:
  StepScanner(std::string_view bytes, const std::string& path, const StepPrecheckLimits& limits)
      : s_(bytes), path_(path), limits_(limits), items_(static_cast<std::size_t>(limits.max_depth) + 2, 0),
        item_open_(static_cast<std::size_t>(limits.max_depth) + 2, false) {}

  StepPrecheckFigures run() {
    while (i_ < s_.size()) step();
    if (depth_ > 0 || too_deep_) {
      if (too_deep_) refuse_too_deep();
      fail("the file ends with " + std::to_string(depth_) + " parentheses open");
    }
    check_references();
    return figures_;
  }

 private:
  [[noreturn]] void fail_at(long line, std::int64_t entity, std::string_view type, const std::string& reason) const {
    std::string where = path_ + ": line " + std::to_string(line);
    if (entity > 0) where += ", #" + std::to_string(entity);
    if (!type.empty()) where += (entity > 0 ? " " : ", ") + std::string(type);
    throw FileError(where + ": " + reason);
  }
  [[noreturn]] void fail(const std::string& reason) const { fail_at(line_, entity_, type_, reason); }

  [[noreturn]] void refuse_too_deep() const {
    fail_at(deep_line_, entity_, type_,
            "parentheses nested " + std::to_string(statement_deepest_) + " deep (the limit is " +
                std::to_string(limits_.max_depth) + ")");
  }

  char peek(std::size_t k) const { return k < s_.size() ? s_[k] : '\0'; }

  // Index of the first byte at or after `k` that is not white space (newlines not counted: look-ahead only).
  std::size_t skip_blanks(std::size_t k) const {
    while (k < s_.size() && (s_[k] == ' ' || s_[k] == '\t' || s_[k] == '\r' || s_[k] == '\n')) ++k;
    return k;
  }

  // A parameter starts at the current depth: counts it as an item of the enclosing list.
  void begin_item() {
    if (depth_ < 1 || depth_ > limits_.max_depth) return;
    const auto d = static_cast<std::size_t>(depth_);
    if (item_open_[d]) return;
    item_open_[d] = true;
    if (++items_[d] > limits_.max_list)
      fail("a list of " + std::to_string(limits_.max_list + 1) + " items or more (the limit is " +
           std::to_string(limits_.max_list) + ")");
  }

  void begin_statement_token() { at_statement_start_ = false; }

  void step() {
    const char c = s_[i_];
    switch (c) {
      case '\n': ++line_; ++i_; return;
      case ' ': case '\t': case '\r': ++i_; return;
      case '/':
        if (peek(i_ + 1) == '*') return skip_comment();
        ++i_;
        return;
      case '\'': begin_item(); return skip_string();
      case '"': begin_item(); return skip_binary();
      case '(': return open();
      case ')': return close();
      case ',':
        if (depth_ >= 1 && depth_ <= limits_.max_depth) item_open_[static_cast<std::size_t>(depth_)] = false;
        ++i_;
        return;
      case ';': return end_statement();
      case '=':
        if (depth_ == 0 && entity_ > 0) expect_type_ = true;
        ++i_;
        return;
      case '#': return hash();
      case '$': case '*': begin_item(); ++i_; return;
      case '.':
        if (is_letter(peek(i_ + 1))) return enumeration();
        if (is_digit(peek(i_ + 1))) return number();
        ++i_;
        return;
      case '+': case '-':
        if (is_digit(peek(i_ + 1)) || (peek(i_ + 1) == '.' && is_digit(peek(i_ + 2)))) return number();
        if (is_letter(peek(i_ + 1)) && depth_ > 0) return word();
        ++i_;
        return;
      default:
        if (is_digit(c)) return number();
        if (is_letter(c) || c == '!') return word();
        ++i_;  // anything else is OCCT's parser's to judge
    }
  }

  void skip_comment() {
    const long start = line_;
    std::size_t k = i_ + 2;
    while (k + 1 < s_.size() && !(s_[k] == '*' && s_[k + 1] == '/')) {
      if (s_[k] == '\n') ++line_;
      ++k;
    }
    if (k + 1 >= s_.size()) fail_at(start, entity_, type_, "a comment that is never closed (no */)");
    i_ = k + 2;
  }

  void skip_string() {
    const long start = line_;
    std::size_t k = i_ + 1;
    for (;;) {
      if (k >= s_.size()) fail_at(start, entity_, type_, "a string that is never closed");
      if (s_[k] == '\'') {
        if (peek(k + 1) != '\'') break;
        k += 2;  // '' is a quote inside the string
        continue;
      }
      if (s_[k] == '\n') ++line_;
      ++k;
    }
    i_ = k + 1;
  }

  void skip_binary() {
    const long start = line_;
    std::size_t k = i_ + 1;
    while (k < s_.size() && s_[k] != '"') {
      if (s_[k] == '\n') ++line_;
      ++k;
    }
    if (k >= s_.size()) fail_at(start, entity_, type_, "a binary literal that is never closed");
    i_ = k + 1;
  }

  void enumeration() {
    std::size_t k = i_ + 1;
    while (k < s_.size() && (is_letter(s_[k]) || is_digit(s_[k]))) ++k;
    if (peek(k) != '.') fail("an enumeration " + quoted(s_.substr(i_, k - i_)) + " not closed by '.'");
    begin_item();
    i_ = k + 1;
  }

  void open() {
    begin_statement_token();
    begin_item();
    ++depth_;
    if (depth_ > statement_deepest_) statement_deepest_ = depth_;
    if (depth_ > figures_.deepest) figures_.deepest = depth_;
    if (depth_ > limits_.max_depth) {
      if (!too_deep_) deep_line_ = line_;
      too_deep_ = true;  // refused when the statement ends, with its full depth
    } else {
      items_[static_cast<std::size_t>(depth_)] = 0;
      item_open_[static_cast<std::size_t>(depth_)] = false;
    }
    ++i_;
  }

  void close() {
    if (depth_ == 0) fail("')' without a matching '('");
    if (depth_ <= limits_.max_depth) {
      const std::size_t items = items_[static_cast<std::size_t>(depth_)];
      if (items > figures_.longest_list) figures_.longest_list = items;
    }
    --depth_;
    ++i_;
  }

  void end_statement() {
    if (too_deep_) refuse_too_deep();
    if (depth_ != 0) fail("';' with " + std::to_string(depth_) + " parentheses still open");
    entity_ = 0;
    type_ = {};
    expect_type_ = false;
    at_statement_start_ = true;
    statement_deepest_ = 0;
    ++i_;
  }

  // Digits after `k` as a number capped above largest_int; `end` gets the index after them.
  std::int64_t digits_value(std::size_t k, std::size_t& end) const {
    std::int64_t value = 0;
    while (k < s_.size() && is_digit(s_[k])) {
      if (value <= largest_int) value = value * 10 + (s_[k] - '0');
      ++k;
    }
    end = k;
    return value;
  }

  void hash() {
    std::size_t end = 0;
    const std::int64_t id = digits_value(i_ + 1, end);
    const std::string_view token = s_.substr(i_, end - i_);
    if (end == i_ + 1) fail("'#' without an entity number");
    if (id > largest_int || id == 0)
      fail("entity number " + quoted(token) + " is outside OCCT's range (1 to " + std::to_string(largest_int) + ")");
    if (depth_ == 0 && at_statement_start_) {  // #N = ...: an instance defined
      begin_statement_token();
      entity_ = id;
      type_ = {};
      if (in_data_) {
        defined_.insert(static_cast<std::int32_t>(id));
        ++figures_.entities;
      }
    } else {
      begin_item();
      if (in_data_) {
        references_.push_back({id, line_, entity_, type_});
        ++figures_.references;
      }
    }
    i_ = end;
  }

  void number() {
    std::size_t k = i_;
    if (s_[k] == '+' || s_[k] == '-') ++k;
    bool real = false;
    const std::size_t integer_start = k;
    while (k < s_.size() && is_digit(s_[k])) ++k;
    const std::size_t integer_digits = k - integer_start;
    std::int64_t exponent = 0;
    if (peek(k) == '.') {
      real = true;
      ++k;
      while (k < s_.size() && is_digit(s_[k])) ++k;
    }
    if (peek(k) == 'E' || peek(k) == 'e') {
      std::size_t e = k + 1;
      if (peek(e) == '+' || peek(e) == '-') ++e;
      if (is_digit(peek(e))) {
        real = true;
        exponent = digits_value(e, k);
        if (s_[e - 1] == '-') exponent = -exponent;
      }
    }
    const std::string_view token = s_.substr(i_, k - i_);
    begin_item();
    // Below 10^300 for sure (integer digits + exponent): no need for strtod, which costs most of the pass.
    if (real) {
      if (static_cast<std::int64_t>(integer_digits) + exponent > 300) {
        token_.assign(token);
        if (!std::isfinite(std::strtod(token_.c_str(), nullptr)))
          fail("the number " + quoted(token) + " does not fit a double");
      }
    } else {
      std::size_t end = 0;
      const std::size_t first_digit = (token[0] == '+' || token[0] == '-') ? i_ + 1 : i_;
      if (digits_value(first_digit, end) > largest_int + (token[0] == '-' ? 1 : 0))
        fail("the integer " + quoted(token) + " does not fit OCCT's 32-bit integers");
    }
    i_ = k;
  }

  void word() {
    std::size_t k = i_ + 1;
    while (k < s_.size() && is_keyword_char(s_[k])) ++k;
    const std::string_view token = s_.substr(i_, k - i_);
    const std::string_view name = (token[0] == '+' || token[0] == '-') ? token.substr(1) : token;
    const bool typed = peek(skip_blanks(k)) == '(';
    if (depth_ == 0 && at_statement_start_) {  // a header entity or a section keyword
      begin_statement_token();
      type_ = token;
      if (token == "DATA") in_data_ = true;
      else if (token == "ENDSEC" || token == "HEADER") in_data_ = false;
    } else if (expect_type_) {  // the type of #N = TYPE(...) or the first part of #N = (A(...) B(...))
      type_ = token;
      expect_type_ = false;
    } else if (depth_ > 0 && !typed) {
      if (names_non_finite(name)) fail(quoted(token) + " is not a finite number");
      fail(quoted(token) + " where a parameter is expected");
    }
    if (depth_ > 0) begin_item();
    i_ = k;
  }

  void check_references() const {
    for (const Reference& reference : references_)
      if (defined_.count(static_cast<std::int32_t>(reference.target)) == 0)
        fail_at(reference.line, reference.entity, reference.type,
                "refers to #" + std::to_string(reference.target) + ", which the file lacks");
  }

  std::string_view s_;
  const std::string& path_;
  StepPrecheckLimits limits_;
  std::size_t i_ = 0;
  long line_ = 1;

  std::int64_t entity_ = 0;  // the instance being read (0: none, or a header entity)
  std::string_view type_;    // its type (the first one of a complex instance)
  bool expect_type_ = false;
  bool at_statement_start_ = true;
  bool in_data_ = false;

  int depth_ = 0;
  int statement_deepest_ = 0;
  bool too_deep_ = false;
  long deep_line_ = 0;
  std::vector<std::size_t> items_;  // items of the open list at each depth up to the limit
  std::vector<bool> item_open_;     // an item of that list has begun since its last ','

  std::unordered_set<std::int32_t> defined_;
  std::vector<Reference> references_;
  std::string token_;
  StepPrecheckFigures figures_;
};

}  // namespace

StepPrecheckFigures precheck_step(std::string_view bytes, const std::string& path, const StepPrecheckLimits& limits) {
  return StepScanner(bytes, path, limits).run();
}

StepPrecheckFigures precheck_step_file(const std::string& path, const StepPrecheckLimits& limits) {
  const std::string bytes = read_file(path);
  return precheck_step(bytes, path, limits);
}

}  // namespace cadnurbs
