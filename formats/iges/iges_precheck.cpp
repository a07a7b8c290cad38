#include "formats/iges/iges_precheck.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <vector>

#include "formats/common/file_io.hpp"

namespace cadnurbs {

namespace {

// OCCT stores IGES integers as Standard_Integer (int).
constexpr std::int64_t largest_int = std::numeric_limits<std::int32_t>::max();

bool is_digit(char c) { return c >= '0' && c <= '9'; }

std::string quoted(std::string_view token) {
  if (token.size() <= 40) return "'" + std::string(token) + "'";
  return "'" + std::string(token.substr(0, 40)) + "...' (" + std::to_string(token.size()) + " characters)";
}

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
  return text;
}

// A parameter as a number: its kind, and its value when it is an integer.
enum class Kind { integer, real, other };

struct Number {
  Kind kind = Kind::other;
  std::int64_t integer = 0;  // capped above largest_int
};

// Classifies an unquoted IGES parameter ([+-]digits, or a real with '.' and/or an E/D exponent). A real
// is only parsed (strtod) when its size could reach 10^300.
Number classify(std::string_view token, bool& fits) {
  Number out;
  fits = true;
  std::size_t k = 0;
  const bool negative = k < token.size() && token[k] == '-';
  if (k < token.size() && (token[k] == '+' || token[k] == '-')) ++k;
  std::int64_t value = 0;
  const std::size_t integer_start = k;
  while (k < token.size() && is_digit(token[k])) {
    if (value <= largest_int) value = value * 10 + (token[k] - '0');
    ++k;
  }
  const std::size_t integer_digits = k - integer_start;
  bool real = false;
  std::size_t fraction_digits = 0;
  if (k < token.size() && token[k] == '.') {
    real = true;
    ++k;
    while (k < token.size() && is_digit(token[k])) ++k, ++fraction_digits;
  }
  if (integer_digits + fraction_digits == 0) return out;
  std::int64_t exponent = 0;
  if (k < token.size() && (token[k] == 'E' || token[k] == 'e' || token[k] == 'D' || token[k] == 'd')) {
    real = true;
    ++k;
    const bool negative_exponent = k < token.size() && token[k] == '-';
    if (k < token.size() && (token[k] == '+' || token[k] == '-')) ++k;
    if (k == token.size() || !is_digit(token[k])) return out;
    while (k < token.size() && is_digit(token[k])) {
      if (exponent < 100000) exponent = exponent * 10 + (token[k] - '0');
      ++k;
    }
    if (negative_exponent) exponent = -exponent;
  }
  if (k != token.size()) return out;
  if (!real) {
    out.kind = Kind::integer;
    out.integer = negative ? -value : value;
    fits = value <= largest_int + (negative ? 1 : 0);
    return out;
  }
  out.kind = Kind::real;
  if (static_cast<std::int64_t>(integer_digits) + exponent > 300) {
    std::string text(token);
    for (char& c : text)
      if (c == 'D' || c == 'd') c = 'E';
    fits = std::isfinite(std::strtod(text.c_str(), nullptr));
  }
  return out;
}

bool names_non_finite(std::string_view token) {
  std::string lower;
  for (char c : token)
    if (c != '+' && c != '-') lower += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return lower == "inf" || lower == "infinity" || lower == "nan";
}

// One entity's parameters (or the Global section's), parsed from the concatenated data columns.
struct Record {
  std::size_t count = 0;                // parameters, the entity type excluded
  std::array<std::int64_t, 4> first{};  // the first four, when integers
  bool ended = false;                   // the record delimiter was found
};

class IgesChecker {
 public:
  IgesChecker(std::string_view bytes, const std::string& path) : s_(bytes), path_(path) {}

  IgesPrecheckFigures run() {
    split_lines();
    if (lines_.empty() || letter(0) != 'S') return figures_;  // compressed or binary form: not checked here
    check_sections();
    check_global();
    check_entries();
    return figures_;
  }

 private:
  [[noreturn]] void fail(std::size_t line_index, const std::string& context, const std::string& reason) const {
    throw FileError(path_ + ": line " + std::to_string(line_index + 1) + (context.empty() ? "" : " (" + context + ")") +
                    ": " + reason);
  }

  void split_lines() {
    std::size_t start = 0;
    while (start < s_.size()) {
      std::size_t end = s_.find('\n', start);
      if (end == std::string_view::npos) end = s_.size();
      std::string_view line = s_.substr(start, end - start);
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      lines_.push_back(line);
      start = end + 1;
    }
    // Blank lines (or NUL padding) after the Terminate line are not part of the file.
    while (!lines_.empty() && lines_.back().find_first_not_of(std::string_view(" \t\0\x1a", 4)) == std::string_view::npos)
      lines_.pop_back();
  }

  char letter(std::size_t index) const { return lines_[index].size() >= 73 ? lines_[index][72] : '\0'; }

  void check_sections() {
    static const std::string_view order = "SGDPT";
    static const std::array<const char*, 5> names = {"Start", "Global", "Directory Entry", "Parameter Data", "Terminate"};
    std::size_t section = 0;
    std::array<std::size_t, 5> counts{};
    for (std::size_t index = 0; index < lines_.size(); ++index) {
      const char c = letter(index);
      const std::size_t which = order.find(c);
      if (c == '\0' || which == std::string_view::npos)
        fail(index, "", lines_[index].size() < 73
                            ? "a line of " + std::to_string(lines_[index].size()) + " columns (no section letter in column 73)"
                            : quoted(std::string_view(&lines_[index][72], 1)) + " in column 73 is not a section letter (S, G, D, P, T)");
      if (which < section)
        fail(index, "", std::string("a ") + names[which] + " section line after the " + names[section] + " section");
      if (section == 4) fail(index, "", "a line after the Terminate line");
      section = which;
      ++counts[which];
      if (which == 2) d_lines_.push_back(index);
      if (which == 3) p_lines_.push_back(index);
      if (which == 1) g_lines_.push_back(index);
    }
    if (counts[4] != 1) fail(lines_.size() - 1, "", "no Terminate line at the end of the file");
    const std::string_view terminate = lines_.back();
    for (std::size_t k = 0; k < 4; ++k) {
      const std::string_view field = terminate.substr(8 * k, 8);
      bool fits = true;
      const Number number = field.size() == 8 && field[0] == order[k] ? classify(trimmed(field.substr(1)), fits) : Number{};
      if (number.kind != Kind::integer || !fits)
        fail(lines_.size() - 1, "Terminate section", "field " + std::to_string(k + 1) + " " + quoted(field) + " is not '" +
                                                         order[k] + "' and a line count");
      if (static_cast<std::size_t>(number.integer) != counts[k])
        fail(lines_.size() - 1, "Terminate section",
             "it counts " + std::to_string(number.integer) + " " + names[k] + " lines, the file has " + std::to_string(counts[k]));
    }
    if (d_lines_.size() % 2 != 0)
      fail(d_lines_.back(), "", "the Directory Entry section has an odd number of lines (" + std::to_string(d_lines_.size()) + ")");
    figures_.directory_entries = d_lines_.size() / 2;
  }

  // The Global section: its first two parameters name the delimiters (1H, and 1H; when left empty).
  void check_global() {
    text_.clear();
    for (std::size_t index : g_lines_) {
      text_.append(lines_[index].substr(0, 72));
    }
    if (text_.empty()) return;
    std::size_t k = 0;
    if (text_.compare(0, 2, "1H") == 0 && text_.size() > 2) {
      parameter_delimiter_ = text_[2];
      k = 3;
    }
    if (k < text_.size() && text_[k] == parameter_delimiter_) {
      ++k;
      if (text_.compare(k, 2, "1H") == 0 && text_.size() > k + 2) {
        record_delimiter_ = text_[k + 2];
        k += 3;
      }
    }
    const auto line_of = [&](std::size_t offset) { return g_lines_[std::min(offset / 72, g_lines_.size() - 1)]; };
    parse_record(0, k, [&](std::size_t offset, std::size_t parameter) {
      return std::make_pair(line_of(offset), "Global section, parameter " + std::to_string(parameter + 3));
    });
  }

  // Parses text_ from `k` to the record delimiter, checking every parameter; `where(offset, parameter)`
  // gives the line index and context of a fault.
  template <class Where>
  Record parse_record(std::size_t first_parameter, std::size_t k, const Where& where) {
    Record record;
    std::size_t parameter = first_parameter;
    while (k < text_.size()) {
      const std::size_t start = k;
      while (k < text_.size() && text_[k] == ' ') ++k;
      // nH...: a string of n characters, which may hold the delimiters.
      std::size_t digits_end = k;
      while (digits_end < text_.size() && is_digit(text_[digits_end])) ++digits_end;
      std::size_t end;
      if (digits_end > k && digits_end < text_.size() && text_[digits_end] == 'H') {
        std::int64_t length = 0;
        for (std::size_t d = k; d < digits_end; ++d)
          if (length <= largest_int) length = length * 10 + (text_[d] - '0');
        if (length > static_cast<std::int64_t>(text_.size() - digits_end - 1)) {
          const auto [line, context] = where(start, parameter);
          fail(line, context, "a string of " + std::to_string(length) + " characters runs past the end of the record");
        }
        end = digits_end + 1 + static_cast<std::size_t>(length);
        while (end < text_.size() && text_[end] == ' ') ++end;
      } else {
        end = k;
        while (end < text_.size() && text_[end] != parameter_delimiter_ && text_[end] != record_delimiter_) ++end;
        const std::string_view token = trimmed(std::string_view(text_).substr(k, end - k));
        if (!token.empty()) {
          bool fits = true;
          const Number number = classify(token, fits);
          const auto fault = [&](const std::string& reason) {
            const auto [line, context] = where(start, parameter);
            fail(line, context, reason);
          };
          if (number.kind == Kind::other)
            fault(names_non_finite(token) ? quoted(token) + " is not a finite number" : quoted(token) + " is not a number");
          if (!fits)
            fault(number.kind == Kind::integer ? "the integer " + quoted(token) + " does not fit OCCT's 32-bit integers"
                                               : "the number " + quoted(token) + " does not fit a double");
          if (number.kind == Kind::integer && parameter < record.first.size()) record.first[parameter] = number.integer;
        }
      }
      ++parameter;
      ++figures_.parameters;
      if (end >= text_.size()) break;
      if (text_[end] == record_delimiter_) {
        record.ended = true;
        break;
      }
      // A string whose count runs over its delimiter (Rhino writes such file names) is followed directly by
      // the next parameter; OCCT reads on, and so do we.
      k = text_[end] == parameter_delimiter_ ? end + 1 : end;
    }
    record.count = parameter - first_parameter;
    return record;
  }

  // The integer in the 8-column field `field` (1-based) of a Directory Entry line; blank is 0.
  std::int64_t field(std::size_t line_index, std::size_t number, const char* name, const std::string& context) const {
    const std::string_view line = lines_[line_index];
    const std::string_view text = trimmed(line.substr(std::min(line.size(), 8 * (number - 1)), 8));
    if (text.empty()) return 0;
    bool fits = true;
    const Number value = classify(text, fits);
    if (value.kind != Kind::integer || !fits)
      fail(line_index, context, std::string("its ") + name + " " + quoted(text) + " is not an integer");
    return value.integer;
  }

  void check_entries() {
    const auto p_count = static_cast<std::int64_t>(p_lines_.size());
    for (std::size_t pair = 0; pair * 2 < d_lines_.size(); ++pair) {
      const std::size_t first = d_lines_[2 * pair], second = d_lines_[2 * pair + 1];
      const std::size_t entry = 2 * pair + 1;
      const std::string context = "directory entry " + std::to_string(entry);
      const std::int64_t type = field(first, 1, "entity type", context);
      const std::int64_t pointer = field(first, 2, "parameter data pointer", context);
      const std::int64_t line_count = field(second, 4, "parameter line count", context);
      if (pointer < 1 || pointer > p_count)
        fail(first, context, "its parameter data pointer " + std::to_string(pointer) + " is outside the Parameter Data section (lines 1 to " +
                                 std::to_string(p_count) + ")");
      if (line_count < 1 || pointer + line_count - 1 > p_count)
        fail(second, context, "its " + std::to_string(line_count) + " parameter lines from line " + std::to_string(pointer) +
                                  " do not fit the Parameter Data section (" + std::to_string(p_count) + " lines)");
      text_.clear();
      const auto begin = static_cast<std::size_t>(pointer - 1);
      for (std::size_t p = begin; p < begin + static_cast<std::size_t>(line_count); ++p) {
        const std::string_view line = lines_[p_lines_[p]];
        const std::int64_t back = trimmed(line.substr(std::min<std::size_t>(line.size(), 64), 8)).empty()
                                      ? 0
                                      : field_at(p_lines_[p], 64, context);
        if (back != static_cast<std::int64_t>(entry))
          fail(p_lines_[p], context, "this Parameter Data line belongs to directory entry " + std::to_string(back));
        text_.append(line.substr(0, 64));
      }
      const auto line_of = [&](std::size_t offset) { return p_lines_[begin + std::min<std::size_t>(offset / 64, line_count - 1)]; };
      // The record starts with the entity type.
      std::size_t k = text_.find_first_of(std::string{parameter_delimiter_, record_delimiter_});
      const std::string_view head = trimmed(std::string_view(text_).substr(0, std::min(k, text_.size())));
      bool fits = true;
      const Number record_type = classify(head, fits);
      if (record_type.kind != Kind::integer || record_type.integer != type)
        fail(line_of(0), context, "its parameter data starts with " + quoted(head) + ", not its entity type " + std::to_string(type));
      if (k == std::string::npos)
        fail(line_of(text_.size() - 1), context,
             std::string("its parameter data has no record delimiter '") + record_delimiter_ + "'");
      if (text_[k] == record_delimiter_) continue;
      const Record record = parse_record(0, k + 1, [&](std::size_t offset, std::size_t parameter) {
        return std::make_pair(line_of(offset), context + ", parameter " + std::to_string(parameter + 1));
      });
      if (!record.ended)
        fail(line_of(text_.size() - 1), context,
             std::string("its parameter data has no record delimiter '") + record_delimiter_ + "'");
      if (record.count > figures_.longest_record) figures_.longest_record = record.count;
      check_counts(type, record, line_of(0), context);
    }
  }

  // Columns 65-72 of a Parameter Data line: the entry it belongs to.
  std::int64_t field_at(std::size_t line_index, std::size_t column, const std::string& context) const {
    const std::string_view text = trimmed(lines_[line_index].substr(column, 8));
    bool fits = true;
    const Number value = classify(text, fits);
    if (value.kind != Kind::integer || !fits)
      fail(line_index, context, "its directory entry pointer " + quoted(text) + " is not an integer");
    return value.integer;
  }

  // B-spline curves (126) and surfaces (128) declare their sizes first; OCCT allocates from them.
  void check_counts(std::int64_t type, const Record& record, std::size_t line, const std::string& context) const {
    const auto n = static_cast<std::int64_t>(record.count);
    const auto refuse = [&](const std::string& declared, const std::string& needed) {
      fail(line, context, "entity " + std::to_string(type) + " declares " + declared + ", which needs " + needed +
                              " parameters; its record has " + std::to_string(n));
    };
    // Each count is at most n (else it needs more than n parameters), so the products below fit.
    const auto out_of_range = [&](std::int64_t count) { return count < 0 || count > n; };
    if (type == 126 && n >= 2) {
      const std::int64_t k = record.first[0], m = record.first[1];
      const std::string declared = "K = " + std::to_string(k) + ", M = " + std::to_string(m);
      if (out_of_range(k) || out_of_range(m)) refuse(declared, "more than " + std::to_string(n));
      const std::int64_t needed = 5 * k + m + 14;  // the normal (3 more) may be left out
      if (needed > n) refuse(declared, std::to_string(needed));
    }
    if (type == 128 && n >= 4) {
      const std::int64_t k1 = record.first[0], k2 = record.first[1], m1 = record.first[2], m2 = record.first[3];
      const std::string declared = "K1 = " + std::to_string(k1) + ", K2 = " + std::to_string(k2) + ", M1 = " + std::to_string(m1) +
                                   ", M2 = " + std::to_string(m2);
      if (out_of_range(k1) || out_of_range(k2) || out_of_range(m1) || out_of_range(m2))
        refuse(declared, "more than " + std::to_string(n));
      const std::int64_t needed = 17 + k1 + m1 + k2 + m2 + 4 * (k1 + 1) * (k2 + 1);
      if (needed > n) refuse(declared, std::to_string(needed));
    }
  }

  std::string_view s_;
  const std::string& path_;
  std::vector<std::string_view> lines_;
  std::vector<std::size_t> g_lines_, d_lines_, p_lines_;  // line indices of each section
  char parameter_delimiter_ = ',';
  char record_delimiter_ = ';';
  std::string text_;  // the data columns of the record being checked
  IgesPrecheckFigures figures_;
};

}  // namespace

IgesPrecheckFigures precheck_iges(std::string_view bytes, const std::string& path) {
  return IgesChecker(bytes, path).run();
}

IgesPrecheckFigures precheck_iges_file(const std::string& path) {
  const std::string bytes = read_file(path);
  return precheck_iges(bytes, path);
}

}  // namespace cadnurbs
