#include "web/site/site_index.hpp"

#include <algorithm>
#include <cstdio>
#include <map>

#include "formats/web_text/markup_text.hpp"

namespace cadnurbs {

namespace {

const char* const kStyle = R"(
  body { font: 14px system-ui, sans-serif; margin: 1.5em; color: #222; }
  table { border-collapse: collapse; }
  th, td { padding: 2px 8px; border-bottom: 1px solid #ddd; text-align: left; vertical-align: middle; }
  td.n, th.n { text-align: right; font-variant-numeric: tabular-nums; }
  img { width: 160px; height: 120px; display: block; }
  .failed { color: #a00; }
)";

std::string ratio_text(double ratio) {
  char text[32];
  std::snprintf(text, sizeof text, ratio < 0.1 ? "%.3f\u00d7" : "%.2f\u00d7", ratio);
  return text;
}

std::string size_cell(const SiteFileSize& file) {
  return "<td class=n>" + grouped(file.bytes) + "<br><small>" + grouped(file.gzip_bytes) + " gz</small></td>";
}

struct FamilyTotals {
  int parts = 0, failed = 0;
  long cnb = 0, library_mesh = 0;
};

}  // namespace

std::string site_index_html(const std::string& title, const std::vector<SiteIndexEntry>& entries, const SiteTotals& totals,
                            const std::string& licences) {
  std::map<std::string, FamilyTotals> families;
  std::vector<std::string> labels;  // the outputs' columns, in the order met
  for (const auto& e : entries) {
    FamilyTotals& f = families[e.family];
    ++f.parts;
    f.failed += e.error.empty() ? 0 : 1;
    if (!e.files.empty()) f.cnb += e.files.front().bytes;
    if (e.has_library_mesh && !e.files.empty()) f.library_mesh += e.library_mesh.bytes;
    for (const auto& file : e.files)
      if (std::find(labels.begin(), labels.end(), file.label) == labels.end()) labels.push_back(file.label);
  }
  std::string html = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<link rel=\"icon\" href=\"data:,\">\n<title>" + escape_html(title) +
                     "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n<h1>" + escape_html(title) + "</h1>\n";
  const long site = totals.site();
  html += "<p>" + grouped(static_cast<long>(entries.size())) + " parts. The whole site is " + grouped(site) + " bytes (" +
          grouped(totals.gzip) + " gzip'd): shared viewer and module " + grouped(totals.shared) + ", part pages " +
          grouped(totals.pages) + ", .cnb files " + grouped(totals.cnb) + ", pictures " + grouped(totals.thumbnails) +
          ", this index " + grouped(totals.index) + ".";
  if (totals.parts_with_library_mesh > 0)
    html += " The meshes the library ships for " + grouped(totals.parts_with_library_mesh) + " of these parts are " +
            grouped(totals.library_mesh) + " bytes (" + grouped(totals.library_mesh_gzip) + " gzip'd): the site is <b>" +
            ratio_text(static_cast<double>(site) / totals.library_mesh) + "</b> of them (" +
            ratio_text(static_cast<double>(totals.gzip) / totals.library_mesh_gzip) + " gzip'd against gzip'd).";
  html += " Each page shows the part as its .cnb holds it, meshed in your browser to below one pixel of the view, "
          "and says how far the file lies from the exact part; the pictures here are drawn by cadnurbs from the "
          "same meshes.</p>\n";
  html += "<h2>Families</h2>\n<table>\n<tr><th>family</th><th class=n>parts</th><th class=n>failed</th><th class=n>.cnb "
          "bytes</th><th class=n>library mesh bytes</th><th class=n>.cnb \u00f7 mesh</th></tr>\n";
  for (const auto& [name, f] : families)
    html += "<tr><td>" + escape_html(name.empty() ? "(top)" : name) + "</td><td class=n>" + grouped(f.parts) +
            "</td><td class=n>" + grouped(f.failed) + "</td><td class=n>" + grouped(f.cnb) + "</td><td class=n>" +
            (f.library_mesh > 0 ? grouped(f.library_mesh) + "</td><td class=n>" + ratio_text(static_cast<double>(f.cnb) / f.library_mesh)
                                : "</td><td class=n>") +
            "</td></tr>\n";
  html += "</table>\n<h2>Parts</h2>\n<table>\n<tr><th></th><th>part</th><th>family</th>";
  for (const auto& label : labels) html += "<th class=n>" + escape_html(label) + "</th>";
  html += "<th class=n>library mesh</th><th class=n>.cnb \u00f7 mesh</th></tr>\n";
  for (const auto& e : entries) {
    html += "<tr><td>";
    if (!e.thumbnail.empty())
      html += (e.page.empty() ? "" : "<a href=\"" + escape_html(e.page) + "\">") + "<img loading=lazy alt=\"\" src=\"" +
              escape_html(e.thumbnail) + "\">" + (e.page.empty() ? "" : "</a>");
    html += "</td><td>";
    html += e.page.empty() ? escape_html(e.part) : "<a href=\"" + escape_html(e.page) + "\">" + escape_html(e.part) + "</a>";
    if (!e.error.empty()) html += "<br><span class=failed>" + escape_html(e.error) + "</span>";
    html += "</td><td>" + escape_html(e.family) + "</td>";
    for (const auto& label : labels) {
      const SiteFileSize* file = nullptr;
      for (const auto& f : e.files)
        if (f.label == label) file = &f;
      html += file ? size_cell(*file) : "<td></td>";
    }
    if (e.has_library_mesh) {
      html += size_cell(e.library_mesh);
      html += e.files.empty() || e.library_mesh.bytes == 0
                  ? "<td></td>"
                  : "<td class=n>" + ratio_text(static_cast<double>(e.files.front().bytes) / e.library_mesh.bytes) + "</td>";
    } else {
      html += "<td></td><td></td>";
    }
    html += "</tr>\n";
  }
  html += "</table>\n<p><small>Bytes as written and gzip'd at level 9. The viewer bundles three.js: <a href=\"" + escape_html(licences) +
          "\">versions and licences</a>.</small></p>\n</body>\n</html>\n";
  return html;
}

}  // namespace cadnurbs
