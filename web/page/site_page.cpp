#include "web/page/site_page.hpp"

#include "formats/web_text/base64.hpp"
#include "formats/web_text/markup_text.hpp"
#include "web/page/page_template.hpp"
#include "web/page/viewer_page_assets.hpp"

namespace cadnurbs {

std::string site_part_page(const SitePartPage& page) {
  const std::string assets = page.root + site_assets_folder() + "/";
  return filled_template(viewer_page_asset("site_page.html"),
                         {{"NAME", escape_html(page.name)},
                          {"FAMILY", escape_html(page.family)},
                          {"LIBRARY", escape_html(page.library)},
                          {"INDEX", escape_html(url_path(page.root + "index.html"))},
                          {"PARTURL", escape_html(url_path(page.cnb_file))},
                          {"PARTNAME", escape_html(page.cnb_file)},
                          {"BYTES", grouped(page.cnb_bytes) + " bytes"},
                          {"ASSETS", escape_html(url_path(assets))},
                          {"PICTURE", page.picture_file.empty() ? std::string()
                                      : "<img id=\"cadnurbs-picture\" elementtiming=\"picture\" src=\"" + escape_html(url_path(page.picture_file)) + "\" alt=\"\">"}});
}

std::vector<std::pair<std::string, std::string>> site_assets() {
  return {{"site_start.js", viewer_page_asset("site_start.js")},
          {"viewer.js", viewer_page_asset("viewer.js")},
          {"render_worker.js", viewer_page_asset("render_worker.js")},
          {"mesh_worker.js", viewer_page_asset("mesh_worker.js")},
          {"cadnurbs_wasm.wasm", bytes_of_base64(viewer_page_asset("cadnurbs_wasm.base64"))},
          {"LICENSES.txt", viewer_page_asset("versions") + "\n\n" + viewer_page_asset("licenses")}};
}

}  // namespace cadnurbs
