#pragma once
// Numbers as text with the fewest characters that keep them within a stated precision, because file
// size is what the project measures: the VRML/X3D writers write them, the compaction weighs its choices
// by them. And numbers as text for people (messages, reports), as printf's %g writes them.
#include <string>

namespace cadnurbs {

// How precisely one number must be written.
// - significant_digits > 0: exactly that many significant digits (trailing zeros dropped); wins over tolerance.
// - otherwise tolerance > 0: the fewest significant digits whose value is within `tolerance` (absolute).
// - both zero: the shortest text that reads back as the very same double.
struct NumberPrecision {
  double tolerance = 0.0;
  int significant_digits = 0;
};

// `value` as text: no "-0", integers without a decimal point, no trailing zeros, no leading zero before
// the point (".5"), exponent form ("15e-7") only where it is shorter. Refuses (std::invalid_argument)
// values that are not finite, a negative tolerance and more than 17 significant digits.
std::string format_number(double value, const NumberPrecision& precision);

// The same text appended to `out` (saves an allocation per number in large arrays).
void append_number(std::string& out, double value, const NumberPrecision& precision);

// A figure for people (messages, reports) as printf's "%.<significant_digits>g" writes it: "0.000123",
// "3.34e+03", "-0", "nan", "inf". Numbers in written files go through format_number instead, which is
// shorter and refuses what cannot be read back. significant_digits < 1 counts as 1.
std::string number_text(double value, int significant_digits);

// number_text with three significant digits, the precision of the pipeline's messages.
std::string message_number(double value);

}  // namespace cadnurbs
