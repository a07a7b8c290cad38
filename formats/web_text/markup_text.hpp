#pragma once
// Text put into an HTML page: escaped for element content and attributes, or checked fit to stand inside a
// <script> element, whose text cannot be escaped.
#include <string>

namespace cadnurbs {

// Markup-safe text for element content and quoted attribute values.
std::string escape_html(const std::string& text);

// A relative path ('/'-separated) as a URL path: every byte but letters, digits, '-', '.', '_', '~' and '/'
// percent-encoded, so that a name with spaces, '#' or '?' still links to its file.
std::string url_path(const std::string& path);

// 1234567 -> "1 234 567" (narrow no-break spaces): byte counts people can read.
std::string grouped(long value);

// `text` itself, or std::runtime_error "<what> contains </script or <!-- and cannot be inlined" where it
// would end or confuse a <script> element.
const std::string& script_text(const std::string& text, const std::string& what);

}  // namespace cadnurbs
