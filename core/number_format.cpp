#include "core/number_format.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <system_error>

#include "core/chars_to_double.hpp"

namespace cadnurbs {

namespace {

// A decimal number d1.d2d3...dk x 10^exponent; `digits` has no trailing zeros ("0" for zero).
struct Decimal {
  bool negative = false;
  std::string digits;
  int exponent = 0;
};

// Splits std::to_chars' scientific text ("-1.2340e+05") into a Decimal.
Decimal decimal_from_scientific(const char* first, const char* last) {
  Decimal d;
  const char* p = first;
  if (p != last && *p == '-') {
    d.negative = true;
    ++p;
  }
  for (; p != last && *p != 'e'; ++p)
    if (*p != '.') d.digits.push_back(*p);
  if (p != last) std::from_chars(p + (p[1] == '+' ? 2 : 1), last, d.exponent);
  while (d.digits.size() > 1 && d.digits.back() == '0') d.digits.pop_back();
  if (d.digits == "0") d.negative = false;  // never "-0"
  return d;
}

// Scientific rendering with `significant` digits, or the shortest round trip when significant == 0.
Decimal round_to(double value, int significant) {
  char buffer[64];
#if defined(__cpp_lib_to_chars)
  const auto result = significant > 0
                          ? std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::scientific,
                                          significant - 1)
                          : std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::scientific);
  return decimal_from_scientific(buffer, result.ptr);
#else
  // The browser module's libc++ has no floating-point to_chars (chars_to_double.hpp). printf rounds
  // correctly too; the shortest round trip is the fewest digits whose correct rounding reads back.
  int written = 0;
  for (int digits = significant > 0 ? significant : 1; digits <= 17; ++digits) {
    written = std::snprintf(buffer, sizeof buffer, "%.*e", digits - 1, value);
    double back = 0.0;
    if (significant > 0 || (chars_to_double(buffer, buffer + written, back).ec == std::errc() && back == value)) break;
  }
  return decimal_from_scientific(buffer, buffer + written);
#endif
}

// Plain notation, or exponent notation where that is shorter (plain on a tie, it reads better).
void append_decimal(std::string& out, const Decimal& d) {
  if (d.digits == "0") {
    out.push_back('0');
    return;
  }
  const int k = static_cast<int>(d.digits.size());
  std::string plain;
  if (d.exponent >= k - 1) {
    plain = d.digits + std::string(static_cast<size_t>(d.exponent - (k - 1)), '0');
  } else if (d.exponent >= 0) {
    plain = d.digits.substr(0, static_cast<size_t>(d.exponent) + 1) + "." +
            d.digits.substr(static_cast<size_t>(d.exponent) + 1);
  } else {
    plain = "." + std::string(static_cast<size_t>(-d.exponent - 1), '0') + d.digits;
  }
  if (d.negative) out.push_back('-');
  // Integers stay integers ("1000", not "1e3"): readable, and they rarely have many zeros
  // (astronomic ones excepted).
  if (d.exponent >= k - 1 && d.exponent < 21) {
    out += plain;
    return;
  }
  // Exponent form with an integer mantissa ("15e-7") is never longer than "1.5e-6".
  const std::string exponential = d.digits + "e" + std::to_string(d.exponent - (k - 1));
  out += exponential.size() < plain.size() ? exponential : plain;
}

double parse(const Decimal& d) {
  const std::string text = (d.negative ? "-" : "") + d.digits.substr(0, 1) + "." + d.digits.substr(1) + "e" +
                           std::to_string(d.exponent);
  double value = 0.0;
  chars_to_double(text.data(), text.data() + text.size(), value);
  return value;
}

}  // namespace

void append_number(std::string& out, double value, const NumberPrecision& precision) {
  if (!std::isfinite(value)) throw std::invalid_argument("cannot write a number that is not finite");
  if (precision.tolerance < 0.0 || !std::isfinite(precision.tolerance))
    throw std::invalid_argument("number tolerance must be a finite value >= 0");
  if (precision.significant_digits > 17)
    throw std::invalid_argument("at most 17 significant digits are meaningful for a double");
  if (precision.significant_digits > 0) {
    append_decimal(out, round_to(value, precision.significant_digits));
    return;
  }
  if (precision.tolerance > 0.0) {
    if (std::abs(value) <= precision.tolerance) {
      out.push_back('0');
      return;
    }
    // Fewer significant digits never give a longer text, so the first that fits is the shortest.
    for (int k = 1; k <= 17; ++k) {
      const Decimal d = round_to(value, k);
      if (std::abs(parse(d) - value) <= precision.tolerance) {
        append_decimal(out, d);
        return;
      }
    }
  }
  append_decimal(out, round_to(value, 0));
}

std::string format_number(double value, const NumberPrecision& precision) {
  std::string out;
  append_number(out, value, precision);
  return out;
}

std::string number_text(double value, int significant_digits) {
  significant_digits = std::max(significant_digits, 1);
  char text[64];
  const int length = std::snprintf(text, sizeof text, "%.*g", significant_digits, value);
  if (length < static_cast<int>(sizeof text)) return std::string(text, static_cast<size_t>(length));
  // Only a number given more digits than fit needs more room (1e80 with 100 digits).
  std::string longer(static_cast<size_t>(length), '\0');
  std::snprintf(longer.data(), longer.size() + 1, "%.*g", significant_digits, value);
  return longer;
}

std::string message_number(double value) { return number_text(value, 3); }

}  // namespace cadnurbs
