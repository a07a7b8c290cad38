#include "formats/gltf/json_text.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace cadnurbs {

void JsonText::before_value() {
  if (after_key_) {
    after_key_ = false;
    return;
  }
  if (!container_is_empty_.empty()) {
    if (!container_is_empty_.back()) out_ += ',';
    container_is_empty_.back() = false;
  }
}

void JsonText::open(char bracket) {
  before_value();
  out_ += bracket;
  container_is_empty_.push_back(true);
}

void JsonText::close(char bracket) {
  out_ += bracket;
  container_is_empty_.pop_back();
}

JsonText& JsonText::begin_object() { open('{'); return *this; }
JsonText& JsonText::end_object() { close('}'); return *this; }
JsonText& JsonText::begin_array() { open('['); return *this; }
JsonText& JsonText::end_array() { close(']'); return *this; }

JsonText& JsonText::key(std::string_view name) {
  string(name);
  out_ += ':';
  after_key_ = true;
  return *this;
}

JsonText& JsonText::string(std::string_view text) {
  before_value();
  out_ += '"';
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out_ += '\\';
      out_ += c;
    } else if (u < 0x20) {
      static const char* hex = "0123456789abcdef";
      out_ += "\\u00";
      out_ += hex[u >> 4];
      out_ += hex[u & 15];
    } else {
      out_ += c;
    }
  }
  out_ += '"';
  return *this;
}

JsonText& JsonText::number(double value) {
  if (!std::isfinite(value)) throw std::invalid_argument("JSON cannot hold a number that is not finite");
  before_value();
  char buffer[32];
  // to_chars without a format is the shortest round-trip form, always with a leading digit ("0.5").
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value == 0 ? 0.0 : value);
  out_.append(buffer, result.ptr);
  return *this;
}

JsonText& JsonText::integer(std::int64_t value) {
  before_value();
  out_ += std::to_string(value);
  return *this;
}

JsonText& JsonText::boolean(bool value) {
  before_value();
  out_ += value ? "true" : "false";
  return *this;
}

}  // namespace cadnurbs
