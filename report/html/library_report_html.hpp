#pragma once
// The combined report of a whole library (cadnurbs batch, batch --merge) as one self-contained HTML
// page: Chart.js inlined, no request made. One page for thousands of parts, so no per-part charts or
// 3D views (report_html.hpp has those, for a few parts): the bytes of every representation summed over
// the library (table and chart), the distribution of per-part compression ratios (a histogram), the
// failures by reason (a chart and the parts of each), and one table row per part. The numbers come
// from summarise_library (library_summary.hpp); the <html> element gets data-charts="ready" once the
// three charts are drawn.
#include <string>
#include <vector>

#include "report/storage_record.hpp"

namespace cadnurbs {

// The page for `records` (in the order given; batch gives them sorted by part). Every text that comes
// from a record is escaped, so no input name or error can end an element or inject markup.
std::string library_report_html(const std::vector<PartRecord>& records);

}  // namespace cadnurbs
