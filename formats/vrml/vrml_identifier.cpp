#include "formats/vrml/vrml_identifier.hpp"

#include <array>
#include <string_view>

namespace cadnurbs {

namespace {

bool is_reserved(const std::string& word) {
  // Keywords of VRML97 and of the X3D classic encoding; a DEF name may not be one of them.
  static constexpr std::array<std::string_view, 25> reserved = {
      "DEF",        "USE",          "PROTO",         "EXTERNPROTO", "ROUTE",     "TO",       "IS",
      "TRUE",       "FALSE",        "NULL",          "eventIn",     "eventOut",  "field",    "exposedField",
      "AS",         "COMPONENT",    "EXPORT",        "IMPORT",      "META",      "PROFILE",  "UNIT",
      "inputOnly",  "outputOnly",   "inputOutput",   "initializeOnly"};
  for (auto r : reserved)
    if (word == r) return true;
  return false;
}

bool is_identifier_char(unsigned char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
}

}  // namespace

std::string sanitised_identifier(const std::string& name) {
  std::string out;
  for (size_t i = 0; i < name.size(); ++i) {
    const auto c = static_cast<unsigned char>(name[i]);
    if (is_identifier_char(c)) {
      out.push_back(static_cast<char>(c));
    } else {
      out.push_back('_');
      // A multi-byte UTF-8 character becomes one '_', not one per byte.
      while (c >= 0xC0 && i + 1 < name.size() && (static_cast<unsigned char>(name[i + 1]) & 0xC0) == 0x80) ++i;
    }
  }
  if (out.empty() || (out[0] >= '0' && out[0] <= '9') || out[0] == '-') out.insert(out.begin(), '_');
  if (is_reserved(out)) out.push_back('_');
  return out;
}

bool is_generated_identifier(const std::string& identifier) {
  if (identifier.size() < 2 || identifier[0] != '_') return false;
  for (size_t i = 1; i < identifier.size(); ++i)
    if (identifier[i] < '0' || identifier[i] > '9') return false;
  return true;
}

std::string IdentifierRegistry::claim_generated() {
  std::string candidate;
  do candidate = "_" + std::to_string(++generated_);
  while (taken_.count(candidate) != 0);
  taken_.insert(candidate);
  return candidate;
}

std::string IdentifierRegistry::claim(const std::string& wanted) {
  const std::string base = sanitised_identifier(wanted);
  std::string candidate = base;
  for (int n = 2; taken_.count(candidate) != 0; ++n) candidate = base + "_" + std::to_string(n);
  taken_.insert(candidate);
  return candidate;
}

}  // namespace cadnurbs
