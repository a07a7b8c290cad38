#pragma once
// SFInt32/MFInt32 values, which both encodings' parsers read as numbers first.
#include <climits>
#include <cmath>
#include <optional>

namespace cadnurbs {

// The int32 a parsed number stands for, or nothing when it is not a whole number within int32's range.
// Checked before any cast: casting 5.6e34 (or NaN) to int is undefined behaviour (UBSan found it, fuzzing
// the X3D XML reader).
inline std::optional<int> field_integer(double value) {
  if (!(value >= INT_MIN && value <= INT_MAX) || value != std::trunc(value)) return std::nullopt;
  return static_cast<int>(value);
}

}  // namespace cadnurbs
