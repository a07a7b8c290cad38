#pragma once
// The report as one self-contained HTML page: everything it needs (Chart.js, X_ITE, X_ITE's NURBS
// component, stylesheet and tangent-space WebAssembly) is inlined, so the page opens from a file with
// no network access and makes no request at all.
//
// The page holds: the accounting rule; a summary table (one row per measured part); the failed inputs
// with their reasons; per part a bar chart of the bytes of every representation (file as written and
// gzip'd), the storage-against-deviation curve on log-log axes when the record has one, the
// representations' table, and the part drawn by X_ITE as NURBS and as mesh side by side; the papers'
// reference figures, labelled as theirs. The charts read report_json(records), embedded as data.
//
// The 3D views are made when their part scrolls into view and at most 8 live at once (a browser page
// gets about 16 WebGL contexts); a view far out of sight is released and made again on return. Each view's
// holder carries data-state: "waiting", "loading", "ready", "failed" (the message is shown and logged
// with console.error) or "released". The <html> element gets data-charts="ready" once every chart is drawn.
#include <string>
#include <vector>

#include "report/storage_record.hpp"

namespace cadnurbs {

// What the 3D views of one part show: X3D classic-encoding texts (.x3dv), loaded into X_ITE with
// createX3DFromString. An empty text: no view of that kind (a failed part, or none given).
struct PartViews {
  std::string nurbs_x3dv;
  std::string mesh_x3dv;
};

// The page for `records`. `views` is empty (no 3D views) or holds one entry per record, in the same
// order; throws std::invalid_argument otherwise. Embedded texts are escaped so that no input, label or
// scene text can end a <script> element or inject markup; a library file that would (a "</script" in a
// future version) is refused with std::runtime_error naming it, since script text cannot be escaped.
std::string report_html(const std::vector<PartRecord>& records, const std::vector<PartViews>& views = {});

}  // namespace cadnurbs
