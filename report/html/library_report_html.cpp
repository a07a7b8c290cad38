#include "report/html/library_report_html.hpp"

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "report/html/html_text.hpp"
#include "report/library_summary.hpp"
#include "report/report_formats.hpp"
#include "report/html/report_html_assets.hpp"

namespace cadnurbs {

namespace {

const char* const page_style = R"css(
tr.failed td { color: #a33; }
.note, figcaption { color: #555; font-size: 0.85em; }
.chart-box { position: relative; height: 340px; border: 1px solid #ddd; }
figure { margin: 1em 0; }
)css";

const char* const page_script = R"js(
(() => {
  'use strict';
  const library = JSON.parse(document.getElementById('cadnurbs-library-data').textContent);
  const colour = { nurbs: '#2f6db3', mesh: '#d9822b', nurss: '#3c8f4a', loop: '#3c8f4a' };
  const light = { nurbs: '#9cc0e8', mesh: '#f2c08f', nurss: '#a5d6ad', loop: '#a5d6ad' };
  const fixed = { animation: false, responsive: true, maintainAspectRatio: false };
  new Chart(document.getElementById('totals'), {
    type: 'bar',
    data: {
      labels: library.totals.map((t) => t.label),
      datasets: [
        { label: 'files as written', data: library.totals.map((t) => t.bytes), backgroundColor: library.totals.map((t) => colour[t.kind]) },
        { label: "gzip'd (level 9)", data: library.totals.map((t) => t.gzip_bytes), backgroundColor: library.totals.map((t) => light[t.kind]) },
      ],
    },
    options: { ...fixed, indexAxis: 'y', scales: { x: { type: 'logarithmic', title: { display: true, text: 'bytes over the library (logarithmic)' } } } },
  });
  new Chart(document.getElementById('ratios'), {
    type: 'bar',
    data: {
      labels: library.ratio_bins.map((b) => b.label),
      datasets: [{ label: 'parts', data: library.ratio_bins.map((b) => b.parts),
                   backgroundColor: library.ratio_bins.map((b) => (b.high <= 1 ? colour.nurbs : colour.mesh)) }],
    },
    options: { ...fixed, scales: { x: { title: { display: true, text: 'smallest NURBS (or Loop) file / smallest mesh file' } },
                                   y: { title: { display: true, text: 'parts' }, ticks: { precision: 0 } } } },
  });
  if (library.failures.length > 0) new Chart(document.getElementById('failures'), {
    type: 'bar',
    data: { labels: library.failures.map((f) => f.reason),
            datasets: [{ label: 'parts', data: library.failures.map((f) => f.parts), backgroundColor: '#b5452f' }] },
    options: { ...fixed, indexAxis: 'y', scales: { x: { title: { display: true, text: 'parts' }, ticks: { precision: 0 } } } },
  });
  requestAnimationFrame(() => { document.documentElement.dataset.charts = 'ready'; });
})();
)js";

// "1/256", "1/2", "1", "4".
std::string power_of_two_text(double value) {
  if (value >= 1) return report_number(value, 4);
  return "1/" + report_number(1 / value, 4);
}

std::string bin_label(const RatioBin& bin) {
  if (bin.low == 0) return "< " + power_of_two_text(bin.high);
  if (std::isinf(bin.high)) return "\u2265 " + power_of_two_text(bin.low);
  return power_of_two_text(bin.low) + "\u2013" + power_of_two_text(bin.high);
}

std::string chart_data(const LibrarySummary& summary) {
  nlohmann::json data;
  data["totals"] = nlohmann::json::array();
  for (const auto& t : summary.totals)
    data["totals"].push_back({{"label", t.label},
                              {"kind", representation_kind_name(t.kind)},
                              {"bytes", t.bytes},
                              {"gzip_bytes", t.gzip_bytes}});
  data["ratio_bins"] = nlohmann::json::array();
  for (const auto& b : summary.ratio_bins)
    data["ratio_bins"].push_back(
        {{"label", bin_label(b)}, {"high", std::isinf(b.high) ? 1e300 : b.high}, {"parts", b.parts}});
  data["failures"] = nlohmann::json::array();
  for (const auto& f : summary.failures) data["failures"].push_back({{"reason", f.reason}, {"parts", f.parts.size()}});
  return data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string chart(const char* id, const char* label, const std::string& caption) {
  return std::string("<figure><div class=\"chart-box\"><canvas class=\"bars\" id=\"") + id + "\" data-part=\"" + id +
         "\" role=\"img\" aria-label=\"" + label +
         "\"></canvas></div><figcaption>" + caption + "</figcaption></figure>\n";
}

std::string totals_section(const LibrarySummary& s) {
  std::ostringstream out;
  out << "<section id=\"totals-section\"><h2>Bytes per representation, over the library</h2>\n"
      << chart("totals", "bytes per representation",
               "Every file written and read back, summed over the parts that have it: dark, as written; light, "
               "gzip'd at level 9. Blue: NURBS; orange: mesh; green: subdivision control mesh.")
      << "<table><thead><tr><th>representation</th><th>parts</th><th>bytes</th><th>gzip'd</th></tr></thead><tbody>\n";
  for (const auto& t : s.totals)
    out << "<tr><td>" << escape_html(t.label) << "</td><td class=\"n\">" << t.parts << "</td><td class=\"n\">"
        << grouped(t.bytes) << "</td><td class=\"n\">" << grouped(t.gzip_bytes) << "</td></tr>\n";
  out << "</tbody></table></section>\n";
  return out.str();
}

std::string ratio_section(const LibrarySummary& s) {
  std::ostringstream out;
  out << "<section id=\"ratio-section\"><h2>Compression ratios</h2>\n"
      << chart("ratios", "distribution of compression ratios",
               "Per part: the smallest NURBS file (for a part given as a mesh, its fitted Loop control mesh) over "
               "the smallest mesh file at D, each the smaller of the file and its gzip'd form. Blue bins: the "
               "NURBS file is the smaller.")
      << "<p>" << s.smaller_than_mesh << " of " << s.ratio_parts
      << " parts compared have a smooth file smaller than their smallest mesh file.</p></section>\n";
  return out.str();
}

std::string failure_section(const LibrarySummary& s) {
  std::ostringstream out;
  out << "<section id=\"failure-section\"><h2>Failures by reason (" << s.failed << " of " << s.parts << " parts)</h2>\n";
  if (s.failures.empty()) {
    out << "<p>No part failed.</p></section>\n";
    return out.str();
  }
  out << chart("failures", "failures by reason", "Failed parts, grouped by their error with numbers and places left out.")
      << "<table><thead><tr><th>reason</th><th>parts</th><th>which</th></tr></thead><tbody>\n";
  for (const auto& f : s.failures) {
    out << "<tr><td>" << escape_html(f.reason) << "</td><td class=\"n\">" << f.parts.size() << "</td><td>";
    for (std::size_t i = 0; i < f.parts.size(); ++i)
      out << (i ? ", " : "") << "<code>" << escape_html(f.parts[i]) << "</code>";
    out << "</td></tr>\n";
  }
  out << "</tbody></table></section>\n";
  return out.str();
}

std::string parts_table(const std::vector<PartRecord>& records) {
  std::ostringstream out;
  out << "<section id=\"parts\"><h2>Parts</h2>\n<table><thead><tr><th>part</th><th>D</th><th>smallest NURBS file</th>"
         "<th>bytes</th><th>smallest mesh file</th><th>bytes</th><th>NURBS / mesh</th></tr></thead><tbody>\n";
  for (const auto& r : records) {
    if (r.failed) {
      out << "<tr class=\"failed\"><td>" << escape_html(r.input) << "</td><td colspan=\"6\">failed: " << escape_html(r.error)
          << "</td></tr>\n";
      continue;
    }
    const auto* nurbs = smallest_smooth_representation(r);
    const auto* mesh = smallest_representation(r, RepresentationKind::mesh);
    const double ratio = compression_ratio(r);
    out << "<tr><td>" << escape_html(r.input) << "</td><td class=\"n\">" << report_number(r.deviation) << " "
        << escape_html(r.unit) << "</td><td>" << (nurbs ? escape_html(nurbs->label) : "-") << "</td><td class=\"n\">"
        << (nurbs ? grouped(delivered_bytes(*nurbs)) : "-") << "</td><td>" << (mesh ? escape_html(mesh->label) : "-")
        << "</td><td class=\"n\">" << (mesh ? grouped(delivered_bytes(*mesh)) : "-") << "</td><td class=\"n\">"
        << (std::isnan(ratio) ? "-" : report_number(ratio, 3))
        << "</td></tr>\n";
  }
  out << "</tbody></table></section>\n";
  return out.str();
}

}  // namespace

std::string library_report_html(const std::vector<PartRecord>& records) {
  const LibrarySummary summary = summarise_library(records);
  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
         "<meta name=\"generator\" content=\"cadnurbs\">\n<title>cadnurbs library report</title>\n<style>"
      << base_page_style << page_style << "</style>\n<script>" << inline_script("chart.umd.min.js") << "</script>\n"
      << "</head><body>\n<header><h1>cadnurbs library report</h1>\n<p>" << summary.parts << " parts: " << summary.measured
      << " converted and measured, " << summary.failed << " failed.</p>\n<p class=\"note\">"
      << escape_html(accounting_rule()) << "</p></header>\n"
      << totals_section(summary) << ratio_section(summary) << failure_section(summary) << parts_table(records)
      << "<footer><p>Made by cadnurbs with " << escape_html(report_html_asset("versions"))
      << ", inlined.</p><details><summary>Licences of the inlined software</summary><pre>"
      << escape_html(report_html_asset("licenses")) << "</pre></details></footer>\n"
      << "<script type=\"application/json\" id=\"cadnurbs-library-data\">" << script_json(chart_data(summary))
      << "</script>\n<script>" << page_script << "</script>\n</body></html>\n";
  return out.str();
}

}  // namespace cadnurbs
