#pragma once
// A lexical pass over a STEP file (ISO 10303-21) before OCCT parses it, refusing what OCCT is known to
// mishandle: OCCT's parser recurses once per parenthesis (100,000 nested ones overflow its stack), builds
// lists in time quadratic in their length (a 1,000,000-item list does not finish), reads integers and
// entity numbers as 32-bit ints, and its shape repair loops on non-finite coordinates. One pass over the
// bytes, memory linear in the number of entity references; no recursion.
#include <cstddef>
#include <string>
#include <string_view>

namespace cadnurbs {

struct StepPrecheckLimits {
  // Deepest parenthesis nesting accepted. Real files nest 4 deep at most (corpus, samples and 1,358
  // KiCad parts); OCCT 7.6 reads 30,000 and dies of a stack overflow at 100,000 (8 MB stack).
  int max_depth = 64;
  // Longest parameter list accepted. The longest list in the corpus holds 1,018 items, in the KiCad
  // parts 7,262; OCCT 7.6 builds lists in quadratic time: 1.8 s for 50,000 items, 6.8 s for 100,000,
  // 26 s for 200,000 (so about 11 minutes for 1,000,000).
  std::size_t max_list = 100000;
};

// What the pass saw, for measuring real files.
struct StepPrecheckFigures {
  int deepest = 0;               // deepest parenthesis nesting
  std::size_t longest_list = 0;  // most items in one parenthesised list
  std::size_t entities = 0;      // entity instances defined in DATA sections
  std::size_t references = 0;    // #N references in DATA sections
};

// Checks `bytes`, the content of the STEP file `path` (used only in messages). Throws FileError
// "<path>: line L, #N TYPE: <reason>" (or "<path>: line L, TYPE: ..." in the header, "<path>: line L: ..."
// between entities) for: nesting deeper than limits.max_depth, a list longer than limits.max_list, a
// number that is not finite (inf, nan) or does not fit a double (1e400), an integer or entity number
// outside OCCT's 32-bit int, a reference #M that the file does not define, a string, binary literal or
// comment that is not terminated, unbalanced parentheses, a statement not ended by ';', a word where a
// parameter is expected. Does not check the schema (entity types, parameter counts): OCCT does that.
StepPrecheckFigures precheck_step(std::string_view bytes, const std::string& path, const StepPrecheckLimits& limits = {});

// The same over the file at `path` (read whole). Throws FileError also when it cannot be read.
StepPrecheckFigures precheck_step_file(const std::string& path, const StepPrecheckLimits& limits = {});

}  // namespace cadnurbs
