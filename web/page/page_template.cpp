#include "web/page/page_template.hpp"

namespace cadnurbs {

std::string filled_template(const std::string& page, const std::map<std::string, std::string>& values) {
  std::string out;
  std::size_t from = 0;
  for (std::size_t at = page.find('@'); at != std::string::npos; at = page.find('@', from)) {
    const std::size_t end = page.find('@', at + 1);
    const auto value = end == std::string::npos ? values.end() : values.find(page.substr(at + 1, end - at - 1));
    if (value == values.end()) {
      out.append(page, from, at + 1 - from);
      from = at + 1;
      continue;
    }
    out.append(page, from, at - from).append(value->second);
    from = end + 1;
  }
  return out.append(page, from);
}

}  // namespace cadnurbs
