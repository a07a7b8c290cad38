#include "web/page/viewer_page.hpp"

#include "formats/web_text/base64.hpp"
#include "formats/web_text/markup_text.hpp"
#include "web/page/page_template.hpp"
#include "web/page/viewer_page_assets.hpp"

namespace cadnurbs {

std::string viewer_page(const std::string& cnb_bytes, const std::string& name) {
  return filled_template(viewer_page_asset("page.html"),
                         {{"VIEWER", script_text(viewer_page_asset("viewer.js"), "the viewer's script")},
                          {"WORKER", script_text(viewer_page_asset("mesh_worker.js"), "the worker's script")},
                          {"RENDERER", script_text(viewer_page_asset("render_worker.js"), "the renderer's script")},
                          {"WASM", viewer_page_asset("cadnurbs_wasm.base64")},
                          {"PART", base64(cnb_bytes)},
                          {"LICENSES", escape_html(viewer_page_asset("versions") + "\n\n" + viewer_page_asset("licenses"))},
                          {"NAME", escape_html(name)}});
}

}  // namespace cadnurbs
