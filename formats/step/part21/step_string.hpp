#pragma once
// STEP string literals (ISO 10303-21 §6.4.3) to UTF-8. In: the bytes between a literal's quotes, with
// '' still doubled. Out: the text as UTF-8: '' a quote, \\ a backslash, \S\c the character c + 128 of
// ISO 8859-1, \X\hh the ISO 8859-1 character hh, \X2\hhhh...\X0\ UTF-16 (surrogate pairs joined),
// \X4\hhhhhhhh...\X0\ UCS-4; \P?\ code page switches are dropped (everything is read as ISO 8859-1, the
// default page), and line breaks inside the literal are dropped (exporters wrap long lines, and Part 21
// says line breaks carry no content). Refuses nothing: names and descriptions are not worth refusing a
// part for, so a malformed escape stays as its literal characters, an unpaired surrogate or a code
// point past U+10FFFF becomes U+FFFD, and raw bytes above 127 (which Part 21 forbids) are kept when they
// are valid UTF-8 and read as ISO 8859-1 otherwise. The output is always valid UTF-8.
#include <string>
#include <string_view>

namespace cadnurbs::part21 {

// Appends the UTF-8 of `content` (a literal's inside) to `out`.
void append_step_string(std::string_view content, std::string& out);

// The same as a new string.
std::string decode_step_string(std::string_view content);

}  // namespace cadnurbs::part21
