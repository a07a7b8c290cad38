#include "formats/web_text/markup_text.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace cadnurbs {

namespace {

bool contains_ignoring_case(const std::string& text, const std::string& lower_needle) {
  const auto found = std::search(text.begin(), text.end(), lower_needle.begin(), lower_needle.end(),
                                 [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == b; });
  return found != text.end();
}

}  // namespace

std::string escape_html(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

const std::string& script_text(const std::string& text, const std::string& what) {
  if (contains_ignoring_case(text, "</script") || text.find("<!--") != std::string::npos)
    throw std::runtime_error(what + " contains </script or <!-- and cannot be inlined");
  return text;
}

std::string grouped(long value) {
  std::string digits = std::to_string(value < 0 ? -value : value);
  for (int at = int(digits.size()) - 3; at > 0; at -= 3) digits.insert(std::size_t(at), "\u202f");
  return value < 0 ? "-" + digits : digits;
}

std::string url_path(const std::string& path) {
  static const char hex[] = "0123456789ABCDEF";
  std::string out;
  for (const char c : path) {
    const auto byte = static_cast<unsigned char>(c);
    if (std::isalnum(byte) || c == '-' || c == '.' || c == '_' || c == '~' || c == '/') {
      out += c;
    } else {
      out += '%';
      out += hex[byte >> 4];
      out += hex[byte & 15];
    }
  }
  return out;
}

}  // namespace cadnurbs
