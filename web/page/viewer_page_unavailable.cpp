// viewer_page for a cadnurbs built without the browser module (no Emscripten or no zlib source when it was
// configured: web/CMakeLists.txt).
#include <stdexcept>

#include "web/page/viewer_page.hpp"

namespace cadnurbs {

std::string viewer_page(const std::string&, const std::string&) {
  throw std::runtime_error(
      "this cadnurbs was built without the browser module (Emscripten and Debian's zlib source: scripts/setup.sh), "
      "so it cannot write .html");
}

}  // namespace cadnurbs
