#pragma once
// A structural pass over a fixed-format IGES file (80-column lines, section letter in column 73) before
// OCCT reads it, refusing what OCCT would read wrongly or allocate for blindly: sections out of order,
// Terminate counts that do not match, directory entries whose parameter data lies outside the Parameter
// Data section, B-spline entities declaring more control points than their record holds, numbers that
// are not finite, do not fit a double or (integers) OCCT's 32-bit int. Time and memory linear in the
// file size.
#include <cstddef>
#include <string>
#include <string_view>

namespace cadnurbs {

// What the pass saw, for measuring real files.
struct IgesPrecheckFigures {
  std::size_t directory_entries = 0;  // entities (pairs of Directory Entry lines)
  std::size_t parameters = 0;         // parameters in the Global and Parameter Data sections
  std::size_t longest_record = 0;     // most parameters in one entity's record
};

// Checks `bytes`, the content of the IGES file `path` (used only in messages). Throws FileError
// "<path>: line N (directory entry D): <reason>" (or "(Global section, parameter K)", "(Terminate
// section)", or just "line N") for: a line without a section letter, sections not in the order S G D P T,
// Terminate counts unlike the sections' line counts, an odd number of Directory Entry lines, a parameter
// data pointer or line count outside the Parameter Data section, a Parameter Data line pointing back to
// another entry, a record of another entity type than its entry or without its end delimiter, a
// parameter that is not a number or a string, a non-finite or too large number, an entity 126 or 128
// declaring more parameters than its record has. The compressed ('C') and binary forms are not checked.
IgesPrecheckFigures precheck_iges(std::string_view bytes, const std::string& path);

// The same over the file at `path` (read whole). Throws FileError also when it cannot be read.
IgesPrecheckFigures precheck_iges_file(const std::string& path);

}  // namespace cadnurbs
