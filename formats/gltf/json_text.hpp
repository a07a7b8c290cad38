#pragma once
// JSON text built front to back, for the glTF writer: objects, arrays, keys and values in the order they
// are called, commas placed automatically. No document tree: glTF's JSON is small and written once.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace cadnurbs {

class JsonText {
 public:
  JsonText& begin_object();
  JsonText& end_object();
  JsonText& begin_array();
  JsonText& end_array();
  // A member name; the next call gives its value.
  JsonText& key(std::string_view name);
  // A string value, escaped as JSON requires (quotes, backslashes, control characters; UTF-8 passes).
  JsonText& string(std::string_view text);
  // The shortest decimal text that reads back as the same double. Refuses (std::invalid_argument)
  // values that are not finite, which JSON cannot hold.
  JsonText& number(double value);
  JsonText& integer(std::int64_t value);
  JsonText& boolean(bool value);

  // The text so far. Complete once every container that was begun has ended.
  const std::string& text() const { return out_; }

 private:
  void before_value();
  void open(char bracket);
  void close(char bracket);
  std::string out_;
  std::vector<bool> container_is_empty_;
  bool after_key_ = false;
};

}  // namespace cadnurbs
