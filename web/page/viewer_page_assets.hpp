#pragma once
// What the viewer pages inline or share, embedded at build time (web/CMakeLists.txt, cmake/embed_assets.cmake):
//   "page.html"              the self-contained page's template (web/viewer/page.html);
//   "site_page.html"         a site's part page's template (web/viewer/site_page.html);
//   "viewer.js"              the viewer (the page's thread: camera, controls, sketch), bundled by esbuild;
//   "render_worker.js"       the viewer's renderer, a worker with three.js, bundled by esbuild;
//   "site_start.js"          a site page's script: once its picture is painted, starts the mesh worker and
//                            loads the viewer;
//   "mesh_worker.js"         the worker with the module's JavaScript, bundled by esbuild;
//   "cadnurbs_wasm.base64"   the module's WebAssembly, as base64;
//   "versions", "licenses"   the npm packages bundled (three.js) and their licence texts.
// Throws std::out_of_range for another name.
#include <string>

namespace cadnurbs {

const std::string& viewer_page_asset(const std::string& name);

}  // namespace cadnurbs
