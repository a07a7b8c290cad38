#pragma once
// The files the HTML report inlines, as bytes, embedded into the library at build time from the npm
// packages pinned in report/html/package-lock.json (report/html/CMakeLists.txt; the
// build stops with a message naming scripts/setup.sh when they are not installed).
#include <string>

namespace cadnurbs {

// The file `name`, one of:
//   "chart.umd.min.js"       Chart.js (charts);
//   "x_ite.min.js"           X_ITE (X3D browser);
//   "NURBSComponent.min.js"  X_ITE's NURBS component (X_ITE would fetch it beside its script);
//   "x_ite.css"              X_ITE's stylesheet (likewise);
//   "mikktspace_bg.wasm"     X_ITE's tangent generator, which it fetches for every 3D geometry;
//   "versions"               one line: the packages and versions embedded;
//   "licenses"               the licence texts of Chart.js, @kurkle/color (inside Chart.js's bundle) and X_ITE.
// Throws std::out_of_range for another name.
const std::string& report_html_asset(const std::string& name);

}  // namespace cadnurbs
