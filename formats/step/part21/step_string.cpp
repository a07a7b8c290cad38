#include "formats/step/part21/step_string.hpp"

#include <cstddef>
#include <cstdint>

namespace cadnurbs::part21 {

namespace {

constexpr char32_t replacement = 0xFFFD;

void append_utf8(char32_t c, std::string& out) {
  if (c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) c = replacement;
  if (c < 0x80) {
    out += static_cast<char>(c);
  } else if (c < 0x800) {
    out += static_cast<char>(0xC0 | (c >> 6));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else if (c < 0x10000) {
    out += static_cast<char>(0xE0 | (c >> 12));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (c >> 18));
    out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  }
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

// `count` hex digits at s[k..] as a number, or -1 when they are not all there.
std::int64_t hex_value(std::string_view s, std::size_t k, std::size_t count) {
  if (k + count > s.size()) return -1;
  std::int64_t value = 0;
  for (std::size_t j = 0; j < count; ++j) {
    const int digit = hex_digit(s[k + j]);
    if (digit < 0) return -1;
    value = value * 16 + digit;
  }
  return value;
}

bool starts_with_at(std::string_view s, std::size_t k, std::string_view prefix) { return s.substr(k, prefix.size()) == prefix; }

// The length of the valid UTF-8 sequence at s[k] (a byte above 127), or 0.
std::size_t utf8_sequence_length(std::string_view s, std::size_t k) {
  const auto lead = static_cast<unsigned char>(s[k]);
  std::size_t length = 0;
  char32_t c = 0;
  if (lead >= 0xC2 && lead <= 0xDF) length = 2, c = lead & 0x1F;
  else if (lead >= 0xE0 && lead <= 0xEF) length = 3, c = lead & 0x0F;
  else if (lead >= 0xF0 && lead <= 0xF4) length = 4, c = lead & 0x07;
  else return 0;
  if (k + length > s.size()) return 0;
  for (std::size_t j = 1; j < length; ++j) {
    const auto next = static_cast<unsigned char>(s[k + j]);
    if ((next & 0xC0) != 0x80) return 0;
    c = (c << 6) | (next & 0x3F);
  }
  const char32_t smallest[] = {0, 0, 0x80, 0x800, 0x10000};
  if (c < smallest[length] || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) return 0;
  return length;
}

// \X2\ or \X4\ at s[k]: the code units up to \X0\, appended; returns the index after \X0\, or 0 when
// the escape is malformed (then nothing is appended).
std::size_t wide_escape(std::string_view s, std::size_t k, std::size_t digits, std::string& out) {
  std::size_t j = k + 4;
  std::string decoded;
  char32_t high = 0;  // a UTF-16 high surrogate waiting for its low half
  for (;;) {
    if (starts_with_at(s, j, "\\X0\\")) break;
    const std::int64_t unit = hex_value(s, j, digits);
    if (unit < 0) return 0;
    j += digits;
    auto c = static_cast<char32_t>(unit);
    if (digits == 4 && c >= 0xD800 && c <= 0xDBFF) {
      if (high != 0) append_utf8(replacement, decoded);
      high = c;
      continue;
    }
    if (digits == 4 && c >= 0xDC00 && c <= 0xDFFF && high != 0) {
      c = 0x10000 + ((high - 0xD800) << 10) + (c - 0xDC00);
      high = 0;
    } else if (high != 0) {
      append_utf8(replacement, decoded);
      high = 0;
    }
    append_utf8(c, decoded);
  }
  if (high != 0) append_utf8(replacement, decoded);
  out += decoded;
  return j + 4;
}

}  // namespace

void append_step_string(std::string_view s, std::string& out) {
  std::size_t k = 0;
  while (k < s.size()) {
    const char c = s[k];
    if (c == '\'') {  // '' inside a literal is one quote
      out += '\'';
      k += (k + 1 < s.size() && s[k + 1] == '\'') ? 2 : 1;
    } else if (c == '\n' || c == '\r') {
      ++k;
    } else if (static_cast<unsigned char>(c) >= 0x80) {
      const std::size_t length = utf8_sequence_length(s, k);
      if (length > 0) {
        out.append(s.substr(k, length));
        k += length;
      } else {
        append_utf8(static_cast<unsigned char>(c), out);  // ISO 8859-1
        ++k;
      }
    } else if (c != '\\') {
      out += c;
      ++k;
    } else if (starts_with_at(s, k, "\\\\")) {
      out += '\\';
      k += 2;
    } else if (starts_with_at(s, k, "\\S\\") && k + 3 < s.size() && static_cast<unsigned char>(s[k + 3]) < 0x80) {
      append_utf8(static_cast<char32_t>(static_cast<unsigned char>(s[k + 3]) + 0x80), out);
      k += 4;
    } else if (starts_with_at(s, k, "\\P") && k + 3 < s.size() && s[k + 2] >= 'A' && s[k + 2] <= 'I' && s[k + 3] == '\\') {
      k += 4;
    } else if (starts_with_at(s, k, "\\X\\") && hex_value(s, k + 3, 2) >= 0) {
      append_utf8(static_cast<char32_t>(hex_value(s, k + 3, 2)), out);
      k += 5;
    } else if (starts_with_at(s, k, "\\X2\\") || starts_with_at(s, k, "\\X4\\")) {
      const std::size_t after = wide_escape(s, k, s[k + 2] == '2' ? 4 : 8, out);
      if (after == 0) {
        out += '\\';
        ++k;
      } else {
        k = after;
      }
    } else {
      out += '\\';  // a malformed escape stays as written
      ++k;
    }
  }
}

std::string decode_step_string(std::string_view content) {
  std::string out;
  append_step_string(content, out);
  return out;
}

}  // namespace cadnurbs::part21
