#pragma once
// Spelling of single field values shared by the classic and XML encodings.
#include <string>

#include "formats/vrml/node_graph.hpp"

namespace cadnurbs {

// The numbers of a value without brackets: "1 2 3", tuples of MFVec2f/MFVec3f one per line, MFInt32
// index lists broken into lines after each -1. Refuses node and string values (std::logic_error).
void append_numeric_value(std::string& out, const FieldValue& value, const NumberPrecision& precision);

// Whether the value holds only numbers (MF or SF, not bool or int32 scalars).
bool is_numeric_value(const FieldValue& value);

// How many numbers a numeric value holds (1 for scalars).
size_t number_count(const FieldValue& value);

// `text` as a quoted VRML/X3D string: "..." with \" and \\ escaped.
std::string quoted_string(const std::string& text);

}  // namespace cadnurbs
