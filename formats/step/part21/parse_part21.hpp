#pragma once
// The ISO 10303-21 (STEP Part 21) parser: one streaming pass over a file's bytes into a Model. In: the
// whole file. Out: the entity table (simple and complex instances, typed parameters, lists, strings
// decoded to UTF-8), references resolved to entity ids after the pass, the HEADER's FILE_SCHEMA names.
// Refuses (FileError, one line "<path>: line L, #N TYPE: reason"; "<path>: line L, TYPE: ..." in the
// header, "<path>: line L: ..." between instances): a file that does not start with ISO-10303-21; or
// lacks HEADER; or END-ISO-10303-21; (truncated), nesting deeper than max_depth, a list longer than
// max_list, a number that is not finite or does not fit (1e400, inf, nan, an integer past 64 bits), a
// reference to an entity the file does not define (naming the referring instance and its line), an
// entity number defined twice, an unterminated string, comment or binary, unbalanced parentheses, a
// missing ';', anything else where a parameter is expected, a file of 4 GiB or more (the tables index
// with 32 bits). It does not check the schema: types and parameter counts are the builder's to judge.
// No recursion (nesting lives in an array, so hostile nesting cannot overflow the C stack); memory
// linear in the file's size.
#include <cstddef>
#include <string>
#include <string_view>

#include "formats/step/part21/part21_model.hpp"

namespace cadnurbs::part21 {

// As formats/step/step_precheck.hpp explains: real files nest 4 deep and list 7,262 items at most.
struct Part21Limits {
  int max_depth = 64;
  std::size_t max_list = 100000;
};

// bytes: the whole file; path: for messages only.
Model parse_part21(std::string_view bytes, const std::string& path, const Part21Limits& limits = {});

// The file at `path` read whole, then parsed. Throws FileError also when it cannot be read.
Model read_part21_file(const std::string& path, const Part21Limits& limits = {});

}  // namespace cadnurbs::part21
