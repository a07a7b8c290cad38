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

}  // namespace cadnurbs
