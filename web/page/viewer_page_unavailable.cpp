// viewer_page, site_part_page and site_assets for a cadnurbs built without the browser module (no Emscripten
// or no zlib source when it was configured: web/CMakeLists.txt).
#include <stdexcept>

#include "web/page/site_page.hpp"
#include "web/page/viewer_page.hpp"

namespace cadnurbs {

namespace {

[[noreturn]] void unavailable(const char* what) {
  throw std::runtime_error(std::string("this cadnurbs was built without the browser module (Emscripten and Debian's zlib "
                                       "source: scripts/setup.sh), so it cannot write ") + what);
}

}  // namespace

std::string viewer_page(const std::string&, const std::string&) { unavailable(".html"); }

std::string site_part_page(const SitePartPage&) { unavailable("a site"); }

std::vector<std::pair<std::string, std::string>> site_assets() { unavailable("a site"); }

}  // namespace cadnurbs
