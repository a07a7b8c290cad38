#pragma once
// Text for the HTML pages of the reports (report_html, library_report_html): escaping for markup and for
// JSON inside <script>, the inlined libraries, numbers people can read.
#include <string>

#include "formats/web_text/markup_text.hpp"  // escape_html, grouped

namespace cadnurbs {

// The stylesheet both pages start with: body, headings, tables, numbers in cells, the footer.
extern const char* const base_page_style;

// JSON text made safe inside <script type="application/json">: in JSON '<' occurs only inside strings,
// where \u003c means the same, so no "</script" or "<!--" can end or confuse the element.
std::string script_json(const std::string& json);

// A string as JSON, invalid UTF-8 replaced rather than refused (an input path may hold anything).
std::string json_string(const std::string& text);

// An embedded library file (report_html_assets.hpp) for a <script> element. Script text cannot be
// escaped, so one that would end the element early is refused with std::runtime_error naming it (none
// of the pinned versions does; a new version is caught here).
const std::string& inline_script(const std::string& asset);

}  // namespace cadnurbs
