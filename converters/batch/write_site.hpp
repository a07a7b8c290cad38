#pragma once
// `batch --site DIR`: the converted library as a static site (web/page, web/site, web/thumbnail): the shared
// viewer and module once, and per part its .cnb, a page with the viewer, and a picture; then the index,
// which weighs the whole site against the meshes the library ships beside the same parts.
#include <string>
#include <vector>

#include "converters/batch/library_listing.hpp"
#include "report/storage_record.hpp"
#include "web/site/site_index.hpp"

namespace cadnurbs {

struct SiteOptions {
  std::string in_dir, out_dir, site_dir;  // the library, the batch's outputs (OUT_DIR/<part>.cnb), the site
  int jobs = 1;                           // pictures made at a time, each in a worker process
  ProcessLimits limits;                   // per picture
};

struct SiteSummary {
  int pages = 0;               // parts with a page
  int pictures_failed = 0;     // pages whose picture could not be made (their worker logged why)
  SiteTotals totals;
};

constexpr int site_thumbnail_width = 160, site_thumbnail_height = 120;
constexpr double site_thumbnail_deviation = 2e-3;  // of the part's diagonal: below a pixel of the picture

// The site of `parts` (their records in the same order; a failed record gets a row saying why and no page).
// Every page is written (when its text changed); a picture only where the part is new or its .cnb changed.
// The caller must run one thread (pictures are made in forked workers). Throws FileError when SITE_DIR
// cannot be made or written.
SiteSummary write_site(const SiteOptions& options, const std::vector<LibraryPart>& parts,
                       const std::vector<PartRecord>& records);

// The mesh a library ships beside a NURBS part: a file in the same folder named as the part without its
// extension, plus .wrl, .wrz, .x3d or .stl (KiCad: NAME.step beside NAME.wrl); "" when there is none.
std::string library_mesh_beside(const std::string& part_path);

}  // namespace cadnurbs
