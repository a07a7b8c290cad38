// Number formatting: format_number (fewest characters within the tolerance, no "-0", integers as integers)
// and number_text (printf's %g, for messages).
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <limits>
#include <random>

#include "core/number_format.hpp"

namespace cadnurbs {
namespace {

double parsed(const std::string& text) {
  double v = 0.0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  EXPECT_EQ(r.ptr, text.data() + text.size()) << text;
  return v;
}

TEST(NumberFormat, IntegersAreWrittenAsIntegers) {
  EXPECT_EQ(format_number(0.0, {}), "0");
  EXPECT_EQ(format_number(3.0, {}), "3");
  EXPECT_EQ(format_number(-42.0, {}), "-42");
  EXPECT_EQ(format_number(1000.0, {}), "1000");
  EXPECT_EQ(format_number(1000.0, {1e-6, 0}), "1000");
  EXPECT_EQ(format_number(2.0000000001, {1e-6, 0}), "2");
}

TEST(NumberFormat, NeverWritesNegativeZero) {
  EXPECT_EQ(format_number(-0.0, {}), "0");
  EXPECT_EQ(format_number(-1e-9, {1e-6, 0}), "0");
  EXPECT_EQ(format_number(-0.0004, {0, 1}), "-4e-4");
  EXPECT_EQ(format_number(-0.0, {0, 3}), "0");
}

TEST(NumberFormat, DropsTrailingZerosAndTheLeadingZero) {
  EXPECT_EQ(format_number(0.5, {}), ".5");
  EXPECT_EQ(format_number(-0.25, {}), "-.25");
  EXPECT_EQ(format_number(1.5, {0, 6}), "1.5");
  EXPECT_EQ(format_number(12.5, {1e-9, 0}), "12.5");
}

TEST(NumberFormat, UsesExponentOnlyWhereShorter) {
  EXPECT_EQ(format_number(1e-6, {}), "1e-6");           // ".000001" is longer
  EXPECT_EQ(format_number(1.5e-7, {}), "15e-8");        // integer mantissa beats "1.5e-7"
  EXPECT_EQ(format_number(0.001, {}), ".001");          // "1e-3" is as long: plain wins ties
  EXPECT_EQ(format_number(0.0001, {}), "1e-4");
  EXPECT_EQ(format_number(1e25, {}), "1e25");           // astronomic integers in exponent form
}

TEST(NumberFormat, FewestDigitsWithinTolerance) {
  const double third = 1.0 / 3.0;
  EXPECT_EQ(format_number(third, {0.01, 0}), ".33");
  EXPECT_EQ(format_number(third, {0.001, 0}), ".333");
  EXPECT_EQ(format_number(third, {1e-6, 0}), ".333333");
  EXPECT_EQ(format_number(0.70710678118654757, {1e-4, 0}), ".7071");
  EXPECT_EQ(format_number(123.456, {0.5, 0}), "123");
  EXPECT_EQ(format_number(0.149, {0.06, 0}), ".1");   // one digit already within 0.06
  EXPECT_EQ(format_number(0.149, {0.01, 0}), ".15");
  EXPECT_EQ(format_number(0.0004, {0.001, 0}), "0");  // zero is within the tolerance
  // Property: within tolerance, and one digit fewer would not be.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> value(-1000.0, 1000.0);
  std::uniform_int_distribution<int> exponent(-9, 1);
  for (int i = 0; i < 2000; ++i) {
    const double v = value(random);
    const double tolerance = std::pow(10.0, exponent(random)) * 0.37;
    const std::string text = format_number(v, {tolerance, 0});
    EXPECT_LE(std::abs(parsed(text) - v), tolerance) << v << " -> " << text;
    EXPECT_EQ(text.find("-0"), std::string::npos) << text;
    if (text.find('.') != std::string::npos && text.find('e') == std::string::npos) {
      // Significant digits of the text (leading zeros are not); one fewer must miss the tolerance.
      std::string digits;
      for (char c : text)
        if (c >= '0' && c <= '9' && !(digits.empty() && c == '0')) digits.push_back(c);
      if (digits.size() > 1) {
        const std::string fewer = format_number(v, {0, static_cast<int>(digits.size()) - 1});
        EXPECT_GT(std::abs(parsed(fewer) - v), tolerance) << v << " could be " << fewer;
      }
    }
  }
}

TEST(NumberFormat, SignificantDigitsOverrideTolerance) {
  EXPECT_EQ(format_number(3.14159265, {0, 3}), "3.14");
  EXPECT_EQ(format_number(3.14159265, {1e-12, 2}), "3.1");
  EXPECT_EQ(format_number(0.000123456, {0, 2}), "12e-5");
  EXPECT_EQ(format_number(98765.4, {0, 2}), "99000");
  EXPECT_EQ(format_number(2.0, {0, 5}), "2");
}

TEST(NumberFormat, ShortestRoundTripWithoutPrecision) {
  for (double v : {0.1, 1.0 / 3.0, 2.0 / 7.0 * 1e-12, 6.02214076e23, -123456.789, 1e-300}) {
    const std::string text = format_number(v, {});
    EXPECT_EQ(parsed(text), v) << text;
  }
  EXPECT_EQ(format_number(0.1, {}), ".1");
}

TEST(NumberFormat, RefusesWhatCannotBeWritten) {
  EXPECT_THROW(format_number(std::nan(""), {}), std::invalid_argument);
  EXPECT_THROW(format_number(INFINITY, {}), std::invalid_argument);
  EXPECT_THROW(format_number(1.0, {-1.0, 0}), std::invalid_argument);
  EXPECT_THROW(format_number(1.0, {0, 18}), std::invalid_argument);
}

TEST(NumberText, WritesWhatPrintfPercentGWrites) {
  EXPECT_EQ(number_text(0.1, 17), "0.10000000000000001");
  EXPECT_EQ(number_text(-1.0 / 3.0, 17), "-0.33333333333333331");
  EXPECT_EQ(number_text(123456.5, 6), "123456");  // a tie, rounded to even
  EXPECT_EQ(number_text(123456.5, 17), "123456.5");
  EXPECT_EQ(number_text(1234567.0, 6), "1.23457e+06");
  EXPECT_EQ(number_text(0.000123456, 3), "0.000123");
  EXPECT_EQ(number_text(0.0000123, 3), "1.23e-05");
  EXPECT_EQ(number_text(120.0, 6), "120");
  EXPECT_EQ(number_text(1e21, 6), "1e+21");
  EXPECT_EQ(number_text(0.0, 4), "0");
  EXPECT_EQ(number_text(-0.0, 4), "-0");  // unlike format_number: a message shows what the value is
  EXPECT_EQ(number_text(std::numeric_limits<double>::quiet_NaN(), 3), "nan");
  EXPECT_EQ(number_text(-INFINITY, 8), "-inf");
  EXPECT_EQ(number_text(7.0 / 3.0, -1), "2");  // fewer than one digit counts as one (printf: six)
  // Longer than a double's usual text: 1e80 to its last exact digit.
  const std::string exact = "100000000000000000026609864708367276537402401181200809098131977453489758916313088";
  EXPECT_EQ(number_text(1e80, 100), exact);
  EXPECT_EQ(message_number(3337.0), "3.34e+03");
}

TEST(NumberFormat, AppendsToExistingText) {
  std::string out = "x ";
  append_number(out, 0.25, {});
  EXPECT_EQ(out, "x .25");
}

}  // namespace
}  // namespace cadnurbs
