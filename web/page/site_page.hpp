#pragma once
// The pages of a static site of parts (`batch --site`): each part's page names its .cnb and the files every
// page shares (the viewer, the worker, the module's WebAssembly), so that a browser fetches those once for
// the whole site and compiles the module while it downloads. The pages need an HTTP server (browsers start
// no worker from a file:// page); `convert X -o X.html` writes the page that needs none.
#include <string>
#include <utility>
#include <vector>

namespace cadnurbs {

struct SitePartPage {
  std::string name;       // the part, as the page's title
  std::string family;     // its folder in the library
  std::string library;    // the site's title, the index's link text
  std::string cnb_file;   // the part's .cnb, relative to the page
  std::string picture_file;  // its picture, relative to the page, shown until the viewer draws; "" for none
  long cnb_bytes = 0;     // its size, said beside the download link
  std::string root;       // the site's top folder, relative to the page ("", "../", ...)
};

// The folder under the site's top that holds the shared files.
inline const char* site_assets_folder() { return "cadnurbs-assets"; }

// The page. Throws std::runtime_error when this cadnurbs was built without the browser module.
std::string site_part_page(const SitePartPage& page);

// The shared files, as (name, bytes): site_start.js, viewer.js, render_worker.js, mesh_worker.js,
// cadnurbs_wasm.wasm and LICENSES.txt (the bundled packages' versions and licences). Throws as site_part_page.
std::vector<std::pair<std::string, std::string>> site_assets();

}  // namespace cadnurbs
