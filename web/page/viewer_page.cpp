#include "web/page/viewer_page.hpp"

#include <map>

#include "formats/web_text/base64.hpp"
#include "formats/web_text/markup_text.hpp"
#include "web/page/viewer_page_assets.hpp"

namespace cadnurbs {

namespace {

// The template with each @KEY@ of `values` replaced by its value, in one pass: what a value holds is never
// read as a marker, and an @ that starts no known marker stays.
std::string filled(const std::string& page, const std::map<std::string, std::string>& values) {
  std::string out;
  std::size_t from = 0;
  for (std::size_t at = page.find('@'); at != std::string::npos; at = page.find('@', from)) {
    const std::size_t end = page.find('@', at + 1);
    const auto value = end == std::string::npos ? values.end() : values.find(page.substr(at + 1, end - at - 1));
    if (value == values.end()) {
      out.append(page, from, at + 1 - from);
      from = at + 1;
      continue;
    }
    out.append(page, from, at - from).append(value->second);
    from = end + 1;
  }
  return out.append(page, from);
}

}  // namespace

std::string viewer_page(const std::string& cnb_bytes, const std::string& name) {
  return filled(viewer_page_asset("page.html"),
                {{"VIEWER", script_text(viewer_page_asset("viewer.js"), "the viewer's script")},
                 {"WORKER", script_text(viewer_page_asset("mesh_worker.js"), "the worker's script")},
                 {"WASM", viewer_page_asset("cadnurbs_wasm.base64")},
                 {"PART", base64(cnb_bytes)},
                 {"LICENSES", escape_html(viewer_page_asset("versions") + "\n\n" + viewer_page_asset("licenses"))},
                 {"NAME", escape_html(name)}});
}

}  // namespace cadnurbs
