#pragma once
// Bytes as base64 (RFC 4648, with padding), for what a web page carries inline: a data: URL, or a part and
// a WebAssembly module in the page's own elements.
#include <string>

namespace cadnurbs {

std::string base64(const std::string& bytes);

// The bytes `text` codes (base64 as above; whitespace skipped). Throws std::invalid_argument at a character
// that is not base64 or a length that is not whole.
std::string bytes_of_base64(const std::string& text);

}  // namespace cadnurbs
