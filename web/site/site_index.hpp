#pragma once
// The index page of a static site of parts (`batch --site`): what the whole site weighs against the meshes
// the library ships for the same parts, per family and in all, and a row per part: its picture, name and
// family, the bytes of each file written for it and of the library's own mesh, and the ratio of the two.
// Plain HTML and CSS: the index loads no script, and its pictures load as they scroll into view.
#include <string>
#include <vector>

namespace cadnurbs {

// A file's size as written and gzip'd (level 9).
struct SiteFileSize {
  std::string label;  // ".cnb", ".x3dv", "KiCad.wrl", ...
  long bytes = 0, gzip_bytes = 0;
};

struct SiteIndexEntry {
  std::string part;                // its path in the library
  std::string family;              // its folder in the library ("" at the top)
  std::string page, thumbnail;     // relative to the index; "" when there is none
  std::string error;               // why the part has no page ("" when it has)
  std::vector<SiteFileSize> files; // the part's outputs, the .cnb first
  bool has_library_mesh = false;
  SiteFileSize library_mesh;       // the mesh the library ships beside the part
};

// Bytes of the site by what they are.
struct SiteTotals {
  long shared = 0, pages = 0, cnb = 0, thumbnails = 0, index = 0;  // the index: this page itself
  long gzip = 0;                          // every file of the site gzip'd, summed
  long library_mesh = 0, library_mesh_gzip = 0;  // the library's meshes of the parts that have one
  int parts_with_library_mesh = 0;
  long site() const { return shared + pages + cnb + thumbnails + index; }
};

// The page, titled `title`, entries in their order; `licences` links the bundled packages' licences.
std::string site_index_html(const std::string& title, const std::vector<SiteIndexEntry>& entries, const SiteTotals& totals,
                            const std::string& licences);

}  // namespace cadnurbs
