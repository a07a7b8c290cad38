#include "formats/web_text/base64.hpp"

#include <algorithm>
#include <stdexcept>

namespace cadnurbs {

std::string base64(const std::string& bytes) {
  static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    unsigned value = 0;
    for (std::size_t k = 0; k < 3; ++k)
      value = value << 8 | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    for (std::size_t k = 0; k < 4; ++k) out += k <= n ? digits[(value >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

std::string bytes_of_base64(const std::string& text) {
  std::string out;
  out.reserve(text.size() / 4 * 3);
  unsigned value = 0;
  int digits = 0, padding = 0;
  for (const char c : text) {
    int digit;
    if (c >= 'A' && c <= 'Z') digit = c - 'A';
    else if (c >= 'a' && c <= 'z') digit = c - 'a' + 26;
    else if (c >= '0' && c <= '9') digit = c - '0' + 52;
    else if (c == '+') digit = 62;
    else if (c == '/') digit = 63;
    else if (c == '=') digit = 0, ++padding;
    else if (c == ' ' || c == '\n' || c == '\r' || c == '\t') continue;
    else throw std::invalid_argument(std::string("base64: '") + c + "' is not a base64 character");
    if (padding > 0 && c != '=') throw std::invalid_argument("base64: text after its padding");
    value = value << 6 | static_cast<unsigned>(digit);
    if (++digits == 4) {
      for (int k = 0; k < 3 - padding; ++k) out += static_cast<char>((value >> (16 - 8 * k)) & 255);
      value = 0;
      digits = 0;
    }
  }
  if (digits != 0 || padding > 2) throw std::invalid_argument("base64: its length is not a whole number of groups");
  return out;
}

}  // namespace cadnurbs
