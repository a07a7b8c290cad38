#include "core/chars_to_double.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>

namespace cadnurbs {

std::from_chars_result chars_to_double(const char* first, const char* last, double& value) {
#if defined(__cpp_lib_to_chars)
  return std::from_chars(first, last, value);
#else
  if (first == last || *first == '+' || std::isspace(static_cast<unsigned char>(*first)))
    return {first, std::errc::invalid_argument};
  const std::string text(first, last);
  const char* start = text.c_str();
  const bool negative = text[0] == '-';
  // from_chars reads "0x1p3" as the number 0 followed by other text; strtod would read hexadecimal.
  if (text.size() > negative + 1u && text[negative] == '0' && (text[negative + 1] == 'x' || text[negative + 1] == 'X')) {
    value = negative ? -0.0 : 0.0;
    return {first + negative + 1, std::errc()};
  }
  char* end = nullptr;
  errno = 0;
  const double parsed = std::strtod(start, &end);
  if (end == start)
    return {first, std::errc::invalid_argument};
  if (errno == ERANGE && std::isinf(parsed)) return {first + (end - start), std::errc::result_out_of_range};
  value = parsed;
  return {first + (end - start), std::errc()};
#endif
}

}  // namespace cadnurbs
