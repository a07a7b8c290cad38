#include "formats/step/part21/parse_part21.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <system_error>
#include <vector>

#include "formats/common/file_io.hpp"
#include "formats/step/part21/step_string.hpp"

namespace cadnurbs::part21 {

namespace {

using detail::Slot;

enum CharClass : std::uint8_t { other, blank, newline, digit, letter, keyword_only };  // keyword_only: '-'

constexpr std::array<std::uint8_t, 256> char_classes = [] {
  std::array<std::uint8_t, 256> classes{};
  classes[' '] = classes['\t'] = classes['\r'] = classes['\f'] = classes['\v'] = blank;
  classes['\n'] = newline;
  for (int c = '0'; c <= '9'; ++c) classes[c] = digit;
  for (int c = 'A'; c <= 'Z'; ++c) classes[c] = classes[c + 'a' - 'A'] = letter;
  classes['_'] = letter;
  classes['-'] = keyword_only;
  return classes;
}();

CharClass class_of(char c) { return static_cast<CharClass>(char_classes[static_cast<unsigned char>(c)]); }
bool is_digit(char c) { return class_of(c) == digit; }
bool is_letter(char c) { return class_of(c) == letter; }
bool is_keyword_char(char c) { return class_of(c) >= digit; }
bool is_hex_digit(char c) { return is_digit(c) || (c >= 'A' && c <= 'F') || (c >= 'a' && c <= 'f'); }

bool equals_ignoring_case(std::string_view a, std::string_view lower) {
  if (a.size() != lower.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const char x = (a[k] >= 'A' && a[k] <= 'Z') ? static_cast<char>(a[k] - 'A' + 'a') : a[k];
    if (x != lower[k]) return false;
  }
  return true;
}

bool names_non_finite(std::string_view word) {
  if (!word.empty() && (word[0] == '+' || word[0] == '-')) word.remove_prefix(1);
  return equals_ignoring_case(word, "inf") || equals_ignoring_case(word, "infinity") || equals_ignoring_case(word, "nan");
}

std::string parentheses(std::size_t count) {
  return std::to_string(count) + (count == 1 ? " parenthesis" : " parentheses");
}

// A token as quoted in a message, cut at 40 characters.
std::string quoted(std::string_view token) {
  if (token.size() <= 40) return "'" + std::string(token) + "'";
  return "'" + std::string(token.substr(0, 40)) + "...' (" + std::to_string(token.size()) + " characters)";
}

}  // namespace

class Part21Parser {
 public:
  Part21Parser(std::string_view bytes, const std::string& path, const Part21Limits& limits)
      : p_(bytes.data()), end_(bytes.data() + bytes.size()), path_(path), limits_(limits) {
    if (bytes.size() >= (std::uint64_t{1} << 32)) fail("a file of 4 GiB or more (the entity table indexes with 32 bits)");
    // Library parts hold an instance per 47 bytes and a value per 13: reserved so that the tables do not
    // grow by copying (untouched reserve costs address space only).
    model_.slots_.reserve(bytes.size() / 10);
    model_.entities_.reserve(bytes.size() / 32);
    model_.records_.reserve(bytes.size() / 32);
    model_.text_.reserve(bytes.size() / 8);
  }

  Model run() {
    skip_blanks();
    if (word_at_p() != "ISO-10303-21") fail("not a STEP file (it does not start with ISO-10303-21;)");
    p_ += 12;
    expect_semicolon("ISO-10303-21");
    skip_blanks();
    if (word_at_p() != "HEADER") fail("expected HEADER; after ISO-10303-21;, found " + found());
    p_ += 6;
    expect_semicolon("HEADER");
    read_header();
    for (;;) {
      skip_blanks();
      if (p_ == end_) fail("the file ends before END-ISO-10303-21; (truncated?)");
      const std::string_view word = word_at_p();
      if (word == "DATA") {
        p_ += 4;
        skip_blanks();
        if (p_ < end_ && *p_ == '(') {  // edition 3's DATA(name, schemas): read and dropped
          ++p_;
          const std::size_t slots = model_.slots_.size(), text = model_.text_.size();
          type_ = "DATA";
          read_parameters(1);
          type_ = {};
          model_.slots_.resize(slots);
          model_.text_.resize(text);
        }
        expect_semicolon("DATA");
        read_data_section();
      } else if (word == "END-ISO-10303-21") {
        p_ += word.size();
        expect_semicolon("END-ISO-10303-21");
        break;  // what follows (signatures, padding) is not the exchange structure's
      } else {
        fail("expected DATA; or END-ISO-10303-21;, found " + found());
      }
    }
    index_entities();
    resolve_references();
    index_types();
    return std::move(model_);
  }

 private:
  enum class FrameKind : std::uint8_t { record, list, typed };
  struct Frame {
    FrameKind kind;
    TypeId type;            // a typed parameter's
    std::size_t start;      // its first item in pending_
    std::string_view name;  // a typed parameter's type, for messages
  };

  [[noreturn]] void fail_at(long line, std::int64_t entity, std::string_view type, const std::string& reason) const {
    std::string where = path_ + ": line " + std::to_string(line);
    if (entity > 0) where += ", #" + std::to_string(entity);
    if (!type.empty()) where += (entity > 0 ? " " : ", ") + std::string(type);
    throw FileError(where + ": " + reason);
  }
  [[noreturn]] void fail(const std::string& reason) const { fail_at(line_, entity_, type_, reason); }

  // The token at p_ for messages: a word, or one character, or the end of the file.
  std::string found() const {
    if (p_ == end_) return "the end of the file";
    const std::string_view word = word_at_p();
    if (!word.empty()) return quoted(word);
    const char c = *p_;
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F) {
      static const char hex[] = "0123456789ABCDEF";
      return std::string("byte 0x") + hex[static_cast<unsigned char>(c) >> 4] + hex[c & 15];
    }
    return quoted(std::string_view(p_, 1));
  }

  // The keyword at p_ (letters, digits, '_', '-'; a user-defined one starts with '!'), or "".
  std::string_view word_at_p() const {
    if (p_ == end_ || !(is_letter(*p_) || *p_ == '!')) return {};
    const char* q = p_ + 1;
    while (q < end_ && is_keyword_char(*q)) ++q;
    return {p_, static_cast<std::size_t>(q - p_)};
  }

  void skip_blanks() {
    for (;;) {
      while (p_ < end_) {
        const CharClass c = class_of(*p_);
        if (c == blank) {
          ++p_;
        } else if (c == newline) {
          ++line_;
          ++p_;
        } else {
          break;
        }
      }
      if (p_ + 1 < end_ && p_[0] == '/' && p_[1] == '*') {
        skip_comment();
      } else {
        return;
      }
    }
  }

  void skip_comment() {
    const long start = line_;
    const char* q = p_ + 2;
    while (q + 1 < end_ && !(q[0] == '*' && q[1] == '/')) {
      if (*q == '\n') ++line_;
      ++q;
    }
    if (q + 1 >= end_) fail_at(start, entity_, type_, "a comment that is never closed (no */)");
    p_ = q + 2;
  }

  void expect_semicolon(std::string_view after) {
    skip_blanks();
    if (p_ < end_ && *p_ == ';') {
      ++p_;
      return;
    }
    if (p_ < end_ && *p_ == ')') fail("')' without a matching '('");
    fail("expected ';' after " + std::string(after) + ", found " + found());
  }

  TypeId intern(std::string_view name) {
    // A direct-mapped cache before the hash table: a file uses a few dozen types, over and over.
    const std::size_t key = (name.size() * 31 + static_cast<unsigned char>(name[name.size() / 2]) * 7 +
                             static_cast<unsigned char>(name.back())) % type_cache_.size();
    const TypeId cached = type_cache_[key];
    if (cached != none && model_.type_names_[cached] == name) return cached;
    const auto found_type = model_.type_ids_.find(name);
    TypeId id = 0;
    if (found_type != model_.type_ids_.end()) {
      id = found_type->second;
    } else {
      id = static_cast<TypeId>(model_.type_names_.size());
      model_.type_names_.emplace_back(name);
      model_.type_ids_.emplace(std::string(name), id);
    }
    type_cache_[key] = id;
    return id;
  }

  void read_header() {
    for (;;) {
      skip_blanks();
      const std::string_view word = word_at_p();
      if (word.empty()) {
        if (p_ == end_) fail("the file ends inside the HEADER section (truncated?)");
        fail("expected a header entity or ENDSEC;, found " + found());
      }
      p_ += word.size();
      if (word == "ENDSEC") {
        expect_semicolon("ENDSEC");
        return;
      }
      type_ = word;
      skip_blanks();
      if (p_ == end_ || *p_ != '(') fail("expected '(' after " + std::string(word) + ", found " + found());
      ++p_;
      const std::size_t slots = model_.slots_.size(), text = model_.text_.size();
      const auto [first, count] = read_parameters(1);
      if (word == "FILE_SCHEMA" && count >= 1 && model_.slots_[first].kind == ValueKind::list) {
        const Slot& names = model_.slots_[first];
        for (std::uint32_t k = 0; k < names.aux; ++k) {
          const Slot& name = model_.slots_[names.index + k];
          if (name.kind == ValueKind::string) model_.file_schemas_.emplace_back(model_.text_.substr(name.index, name.aux));
        }
      }
      model_.slots_.resize(slots);  // the header's values are not the DATA's
      model_.text_.resize(text);
      expect_semicolon(word);
      type_ = {};
    }
  }

  void read_data_section() {
    for (;;) {
      skip_blanks();
      if (p_ == end_) fail("the file ends inside a DATA section (truncated?)");
      if (*p_ == '#') {
        read_instance();
        continue;
      }
      const std::string_view word = word_at_p();
      if (word == "ENDSEC") {
        p_ += word.size();
        expect_semicolon("ENDSEC");
        return;
      }
      fail("expected an instance '#N = ...' or ENDSEC;, found " + found());
    }
  }

  // Digits at p_ (after '#') as an entity number.
  std::int64_t entity_number() {
    const char* start = p_;
    std::uint64_t number = 0;
    while (p_ < end_ && is_digit(*p_)) {
      number = number * 10 + static_cast<std::uint64_t>(*p_ - '0');
      ++p_;
      // 18 digits always fit; past them, check before each digit more
      if (p_ - start >= 18 && p_ < end_ && is_digit(*p_) &&
          number > (static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()) - 9) / 10)
        fail("the entity number " + quoted(std::string_view(start - 1, p_ - start + 1)) + "... is too large");
    }
    if (p_ == start) fail("'#' without an entity number");
    if (number == 0) fail("the entity number #0 (numbers start at 1)");
    return static_cast<std::int64_t>(number);
  }

  void read_instance() {
    const long start_line = line_;
    ++p_;
    entity_ = 0;
    type_ = {};
    const std::int64_t number = entity_number();
    entity_ = number;
    skip_blanks();
    if (p_ == end_ || *p_ != '=') fail("expected '=' after #" + std::to_string(number) + ", found " + found());
    ++p_;
    skip_blanks();
    Model::Entity entity{number, static_cast<std::uint32_t>(start_line), static_cast<std::uint32_t>(model_.records_.size()), 0, 0};
    const std::string_view word = word_at_p();
    if (!word.empty()) {
      read_record(word, 1);
      entity.record_count = 1;
    } else if (p_ < end_ && *p_ == '(') {  // a complex instance: (A(...) B(...) ...)
      ++p_;
      entity.complex = 1;
      for (;;) {
        skip_blanks();
        if (p_ < end_ && *p_ == ')') {
          ++p_;
          break;
        }
        const std::string_view part = word_at_p();
        if (part.empty()) {
          if (p_ == end_) fail("the file ends with 1 parenthesis open");
          fail("expected a type name or ')' in a complex instance, found " + found());
        }
        if (entity.record_count == 0) type_ = part;
        if (entity.record_count == limits_.max_list) refuse_long_list();  // its records are its list's items
        read_record(part, 2);
        ++entity.record_count;
      }
      if (entity.record_count == 0) fail("a complex instance without any type");
    } else {
      fail("expected a type name after '#" + std::to_string(number) + " =', found " + found());
    }
    expect_semicolon("the instance");
    model_.entities_.push_back(entity);
    entity_ = 0;
    type_ = {};
  }

  // TYPE(parameters) at p_, as one record of the instance, its '(' at `depth`.
  void read_record(std::string_view name, int depth) {
    if (type_.empty()) type_ = name;
    p_ += name.size();
    const TypeId type = intern(name);
    skip_blanks();
    if (p_ == end_ || *p_ != '(') fail("expected '(' after " + std::string(name) + ", found " + found());
    ++p_;
    const auto [first, count] = read_parameters(depth);
    model_.records_.push_back({type, first, count});
  }

  [[noreturn]] void refuse_long_list() const {
    fail("a list of " + std::to_string(limits_.max_list + 1) + " items or more (the limit is " +
         std::to_string(limits_.max_list) + ")");
  }

  void push(const Slot& slot) {
    pending_.push_back(slot);
    if (pending_.size() - frames_.back().start > limits_.max_list) refuse_long_list();
  }

  void open(FrameKind kind, TypeId type, std::string_view name, int base_depth) {
    if (base_depth + static_cast<int>(frames_.size()) > limits_.max_depth)
      fail("parentheses nested more than " + std::to_string(limits_.max_depth) + " deep (the limit is " +
           std::to_string(limits_.max_depth) + ")");
    frames_.push_back({kind, type, pending_.size(), name});
  }

  // The parameters after a record's '(' (at nesting `base_depth`) up to its ')', into slots_: returns
  // the record's first slot and count. Nested lists and typed parameters live in frames_, not on the C
  // stack; a list's items wait in pending_ and move to slots_ together when it closes.
  std::pair<std::uint32_t, std::uint32_t> read_parameters(int base_depth) {
    frames_.clear();
    pending_.clear();
    frames_.push_back({FrameKind::record, none, 0, {}});
    bool expect_value = true;
    bool may_close = true;  // right after '(' (an empty list), not after ','
    for (;;) {
      skip_blanks();
      if (p_ == end_)
        fail("the file ends with " + parentheses(base_depth - 1 + frames_.size()) + " open");
      const char c = *p_;
      if (!expect_value || (c == ')' && may_close)) {
        if (c == ',' && !expect_value) {
          ++p_;
          expect_value = true;
          may_close = false;
          continue;
        }
        if (c == ')') {
          ++p_;
          const Frame frame = frames_.back();
          frames_.pop_back();
          const auto first = static_cast<std::uint32_t>(model_.slots_.size());
          const auto count = static_cast<std::uint32_t>(pending_.size() - frame.start);
          model_.slots_.insert(model_.slots_.end(), pending_.begin() + static_cast<std::ptrdiff_t>(frame.start), pending_.end());
          pending_.resize(frame.start);
          if (frame.kind == FrameKind::record) return {first, count};
          Slot slot{};
          slot.index = first;
          if (frame.kind == FrameKind::list) {
            slot.kind = ValueKind::list;
            slot.aux = count;
          } else {
            if (count != 1)
              fail("the typed parameter " + std::string(frame.name) + "(...) holds " + std::to_string(count) +
                   " values, not one");
            slot.kind = ValueKind::typed;
            slot.aux = frame.type;
          }
          push(slot);
          expect_value = false;
          continue;
        }
        if (c == ';')
          fail("';' with " + parentheses(base_depth - 1 + frames_.size()) + " still open");
        fail("expected ',' or ')' after a parameter, found " + found());
      }
      read_value(base_depth, expect_value, may_close);
    }
  }

  // One parameter at p_: a slot pushed, or a list or typed parameter opened.
  void read_value(int base_depth, bool& expect_value, bool& may_close) {
    Slot slot{};
    const char c = *p_;
    switch (c) {
      case '$':
        slot.kind = ValueKind::unset;
        ++p_;
        break;
      case '*':
        slot.kind = ValueKind::derived;
        ++p_;
        break;
      case '#':
        ++p_;
        slot.kind = ValueKind::reference;
        slot.aux = none;
        slot.integer = entity_number();
        break;
      case '\'':
        read_string(slot);
        break;
      case '"':
        read_binary(slot);
        break;
      case '(':
        open(FrameKind::list, none, {}, base_depth);
        ++p_;
        expect_value = true;
        may_close = true;
        return;
      case '.':
        if (p_ + 1 < end_ && is_letter(p_[1])) {
          read_enumeration(slot);
          break;
        }
        read_number(slot);
        break;
      default:
        if (is_digit(c) || c == '+' || c == '-') {
          read_number(slot);
          break;
        }
        {
          const std::string_view word = word_at_p();
          if (word.empty()) fail(found() + " where a parameter is expected");
          p_ += word.size();
          skip_blanks();
          if (p_ == end_ || *p_ != '(') {
            if (names_non_finite(word)) fail(quoted(word) + " is not a finite number");
            fail(quoted(word) + " where a parameter is expected");
          }
          open(FrameKind::typed, intern(word), word, base_depth);
          ++p_;
          expect_value = true;
          may_close = false;  // a typed parameter holds exactly one value
          return;
        }
    }
    push(slot);
    expect_value = false;
    may_close = false;
  }

  void read_string(Slot& slot) {
    const long start = line_;
    const char* content = p_ + 1;
    const char* q = content;
    bool plain = true;  // no escape, quote, line break or byte above 127: copied as is
    for (;;) {
      q = static_cast<const char*>(std::memchr(q, '\'', static_cast<std::size_t>(end_ - q)));
      if (q == nullptr) fail_at(start, entity_, type_, "a string that is never closed");
      if (q + 1 < end_ && q[1] == '\'') {
        plain = false;
        q += 2;
        continue;
      }
      break;
    }
    const std::string_view text(content, static_cast<std::size_t>(q - content));
    for (const char c : text) {
      if (c == '\n') ++line_;
      if (c == '\\' || c == '\n' || c == '\r' || static_cast<unsigned char>(c) >= 0x80) plain = false;
    }
    slot.kind = ValueKind::string;
    slot.index = model_.text_.size();
    if (plain) model_.text_.append(text);
    else append_step_string(text, model_.text_);
    slot.aux = static_cast<std::uint32_t>(model_.text_.size() - slot.index);
    p_ = q + 1;
  }

  void read_binary(Slot& slot) {
    const char* content = p_ + 1;
    const auto* q = static_cast<const char*>(std::memchr(content, '"', static_cast<std::size_t>(end_ - content)));
    if (q == nullptr) fail("a binary literal that is never closed");
    const std::string_view digits(content, static_cast<std::size_t>(q - content));
    if (digits.empty() || digits[0] < '0' || digits[0] > '3' || !std::all_of(digits.begin(), digits.end(), is_hex_digit))
      fail("the binary literal " + quoted(digits) + " is not a digit 0-3 followed by hex digits");
    store_text(slot, ValueKind::binary, digits);
    p_ = q + 1;
  }

  void read_enumeration(Slot& slot) {
    const char* q = p_ + 1;
    while (q < end_ && (is_letter(*q) || is_digit(*q))) ++q;
    const std::string_view name(p_ + 1, static_cast<std::size_t>(q - p_ - 1));
    if (q == end_ || *q != '.') fail("the enumeration " + quoted(std::string_view(p_, q - p_)) + " is not closed by '.'");
    store_text(slot, ValueKind::enumeration, name);
    p_ = q + 1;
  }

  void store_text(Slot& slot, ValueKind kind, std::string_view text) {
    slot.kind = kind;
    slot.index = model_.text_.size();
    slot.aux = static_cast<std::uint32_t>(text.size());
    model_.text_.append(text);
  }

  void read_number(Slot& slot) {
    const char* start = p_;
    const char* q = p_;
    if (*q == '+' || *q == '-') ++q;
    const char* integer_start = q;
    while (q < end_ && is_digit(*q)) ++q;
    bool has_digits = q > integer_start;
    bool real = false;
    if (q < end_ && *q == '.') {
      real = true;
      const char* fraction = ++q;
      while (q < end_ && is_digit(*q)) ++q;
      has_digits = has_digits || q > fraction;
    }
    if (!has_digits) {
      const std::string_view word = (q < end_ && is_letter(*q)) ? std::string_view(start, 1 + word_at(start + 1).size())
                                                                  : std::string_view(start, q - start);
      if (names_non_finite(word)) fail(quoted(word) + " is not a finite number");
      fail(quoted(word) + " where a parameter is expected");
    }
    if (q < end_ && (*q == 'E' || *q == 'e')) {
      const char* e = q + 1;
      if (e < end_ && (*e == '+' || *e == '-')) ++e;
      if (e < end_ && is_digit(*e)) {
        real = true;
        while (e < end_ && is_digit(*e)) ++e;
        q = e;
      }
    }
    const std::string_view token(start, static_cast<std::size_t>(q - start));
    const char* from = *start == '+' ? start + 1 : start;  // from_chars takes no '+'
    if (real) {
      slot.kind = ValueKind::real;
      auto [end, error] = std::from_chars(from, q, slot.real);
      if (error == std::errc::result_out_of_range) {  // overflow, or an underflow strtod reads as 0 or subnormal
        const std::string copy(token);
        slot.real = std::strtod(copy.c_str(), nullptr);
        if (!std::isfinite(slot.real)) fail("the number " + quoted(token) + " does not fit a double");
      } else if (error != std::errc() || end != q) {
        fail("the number " + quoted(token) + " cannot be read");
      }
    } else {
      slot.kind = ValueKind::integer;
      auto [end, error] = std::from_chars(from, q, slot.integer);
      if (error == std::errc::result_out_of_range) fail("the integer " + quoted(token) + " does not fit 64 bits");
      if (error != std::errc() || end != q) fail("the number " + quoted(token) + " cannot be read");
    }
    p_ = q;
  }

  std::string_view word_at(const char* at) const {
    const char* q = at;
    while (q < end_ && is_keyword_char(*q)) ++q;
    return {at, static_cast<std::size_t>(q - at)};
  }

  [[noreturn]] void fail_for(EntityId id, const std::string& reason) const {
    const Model::Entity& entity = model_.entities_[id];
    fail_at(static_cast<long>(entity.line), entity.number, model_.type_names_[model_.records_[entity.first_record].type], reason);
  }

  [[noreturn]] void refuse_defined_twice(EntityId later, EntityId earlier) const {
    fail_for(later, "#" + std::to_string(model_.entities_[later].number) + " is defined twice (first at line " +
                        std::to_string(model_.entities_[earlier].line) + ")");
  }

  // #number -> id, dense when the numbers are compact; refuses a number defined twice.
  void index_entities() {
    std::int64_t largest = 0;
    for (const Model::Entity& entity : model_.entities_) largest = std::max(largest, entity.number);
    const std::size_t count = model_.entities_.size();
    if (largest <= static_cast<std::int64_t>(4 * count + 1024)) {
      model_.dense_ids_.assign(static_cast<std::size_t>(largest), none);
      for (EntityId id = 0; id < count; ++id) {
        EntityId& slot = model_.dense_ids_[static_cast<std::size_t>(model_.entities_[id].number - 1)];
        if (slot != none) refuse_defined_twice(id, slot);
        slot = id;
      }
      return;
    }
    auto& sorted = model_.sorted_ids_;
    sorted.reserve(count);
    for (EntityId id = 0; id < count; ++id) sorted.emplace_back(model_.entities_[id].number, id);
    std::sort(sorted.begin(), sorted.end());
    EntityId first_twice = none, earlier = none;
    for (std::size_t k = 1; k < sorted.size(); ++k)
      if (sorted[k].first == sorted[k - 1].first && sorted[k].second < first_twice) {
        first_twice = sorted[k].second;
        earlier = sorted[k - 1].second;
      }
    if (first_twice != none) refuse_defined_twice(first_twice, earlier);
  }

  // Every #N to its entity id; refuses the first (in file order) that names no entity.
  void resolve_references() {
    std::size_t references = 0;
    for (std::size_t k = 0; k < model_.slots_.size(); ++k) {
      Slot& slot = model_.slots_[k];
      if (slot.kind != ValueKind::reference) continue;
      ++references;
      slot.aux = model_.find(slot.integer);
      if (slot.aux == none) fail_for(owner_of(k), "refers to #" + std::to_string(slot.integer) + ", which the file lacks");
    }
    model_.reference_count_ = references;
  }

  // The entity whose parameters hold slot k: an instance's slots are contiguous and end with its last
  // record's parameters (nested lists are stored before the list holding them).
  EntityId owner_of(std::size_t k) const {
    const auto& entities = model_.entities_;
    const auto after = std::upper_bound(entities.begin(), entities.end(), k, [&](std::size_t slot, const Model::Entity& entity) {
      const Record& last = model_.records_[entity.first_record + entity.record_count - 1];
      return slot < static_cast<std::size_t>(last.first) + last.count;
    });
    return static_cast<EntityId>(after - entities.begin());
  }

  // of_type's table: per type, the entities holding it, in file order.
  void index_types() {
    const std::size_t types = model_.type_names_.size();
    std::vector<std::uint32_t> counts(types + 1, 0);
    // A type written twice in one complex instance lists it once: last_holder remembers who came last
    // (linear, where comparing records pairwise would be quadratic in a hostile instance's records).
    std::vector<EntityId> last_holder(types, none);
    auto for_each_type = [&](EntityId id, auto&& visit) {
      const Model::Entity& entity = model_.entities_[id];
      for (std::uint32_t r = 0; r < entity.record_count; ++r) {
        const TypeId type = model_.records_[entity.first_record + r].type;
        if (last_holder[type] == id) continue;
        last_holder[type] = id;
        visit(type);
      }
    };
    for (EntityId id = 0; id < model_.entities_.size(); ++id) for_each_type(id, [&](TypeId type) { ++counts[type + 1]; });
    for (std::size_t t = 0; t < types; ++t) counts[t + 1] += counts[t];
    model_.type_first_ = counts;
    model_.type_entities_.resize(counts[types]);
    std::fill(last_holder.begin(), last_holder.end(), none);
    for (EntityId id = 0; id < model_.entities_.size(); ++id)
      for_each_type(id, [&](TypeId type) { model_.type_entities_[counts[type]++] = id; });
  }

  const char* p_;
  const char* end_;
  const std::string& path_;
  Part21Limits limits_;
  long line_ = 1;
  std::int64_t entity_ = 0;  // the instance being read, for messages (0: none)
  std::string_view type_;    // its (first) type, or the header entity's
  std::vector<Frame> frames_;
  std::vector<Slot> pending_;
  std::array<TypeId, 256> type_cache_ = filled_with_none();
  Model model_;

  static std::array<TypeId, 256> filled_with_none() {
    std::array<TypeId, 256> ids;
    ids.fill(none);
    return ids;
  }
};

Model parse_part21(std::string_view bytes, const std::string& path, const Part21Limits& limits) {
  return Part21Parser(bytes, path, limits).run();
}

Model read_part21_file(const std::string& path, const Part21Limits& limits) {
  const std::string bytes = read_file(path);
  return parse_part21(bytes, path, limits);
}

}  // namespace cadnurbs::part21
