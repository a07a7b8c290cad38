#pragma once
// Bytes as base64 (RFC 4648, with padding), for what a web page carries inline: a data: URL, or a part and
// a WebAssembly module in the page's own elements.
#include <string>

namespace cadnurbs {

std::string base64(const std::string& bytes);

}  // namespace cadnurbs
