#pragma once
// One self-contained web page showing a part: its .cnb bytes, the WebAssembly module, the meshing worker and
// the viewer (web/viewer, three.js bundled) inlined, so that it works from a file:// URL with no network.
// `convert X -o X.html` writes it.
#include <string>

namespace cadnurbs {

// The page for the .cnb file `cnb_bytes`, titled `name`. Throws std::runtime_error when this cadnurbs was
// built without the browser module (no Emscripten: web/CMakeLists.txt), or when a script to inline would
// end its element early.
std::string viewer_page(const std::string& cnb_bytes, const std::string& name);

}  // namespace cadnurbs
