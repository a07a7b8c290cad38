#include "report/html/html_text.hpp"

#include <nlohmann/json.hpp>

#include "formats/web_text/markup_text.hpp"
#include "report/html/report_html_assets.hpp"

namespace cadnurbs {


const char* const base_page_style = R"css(
body { font-family: sans-serif; margin: 1.5em auto; max-width: 1100px; padding: 0 1em; color: #222; background: #fff; }
h1 { font-size: 1.6em; } h2 { font-size: 1.25em; margin-top: 2em; border-bottom: 1px solid #ccc; }
table { border-collapse: collapse; margin: 0.8em 0; font-size: 0.9em; }
th, td { border: 1px solid #ccc; padding: 0.25em 0.5em; text-align: left; vertical-align: top; }
td.n { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
footer { margin-top: 3em; color: #555; font-size: 0.8em; }
footer pre { white-space: pre-wrap; max-height: 20em; overflow: auto; }
)css";

std::string script_json(const std::string& json) {
  std::string out;
  out.reserve(json.size());
  for (char c : json) {
    if (c == '<')
      out += "\\u003c";
    else
      out += c;
  }
  return out;
}

std::string json_string(const std::string& text) {
  return nlohmann::json(text).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

const std::string& inline_script(const std::string& asset) {
  return script_text(report_html_asset(asset), "HTML report: " + asset);
}

}  // namespace cadnurbs
