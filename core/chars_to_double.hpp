#pragma once
// A double from decimal text, as std::from_chars reads it (general format: no leading '+', no leading
// space, no "0x"; "inf" and "nan" read). Where the standard library has from_chars for floating point
// (__cpp_lib_to_chars) it is that. The browser module's libc++ (Emscripten 3.1.6, Debian 12's) has none:
// there, the text's copy goes to strtod, which musl rounds correctly as from_chars does, after refusing
// what from_chars refuses; an overflow is result_out_of_range and leaves `value` alone.
#include <charconv>

namespace cadnurbs {

std::from_chars_result chars_to_double(const char* first, const char* last, double& value);

}  // namespace cadnurbs
