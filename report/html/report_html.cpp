#include "report/html/report_html.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "formats/web_text/base64.hpp"
#include "report/html/html_text.hpp"
#include "report/reference_figures.hpp"
#include "report/report_formats.hpp"
#include "report/html/report_html_assets.hpp"

namespace cadnurbs {

namespace {

// X_ITE's stylesheet without its icons: their url(assets/...) would be fetched beside the page.
// Only the splash screen and the context menu, both turned off in the report, show them.
std::string x_ite_stylesheet() {
  std::string css = report_html_asset("x_ite.css");
  const std::string start = "url(assets/";
  for (std::size_t at = css.find(start); at != std::string::npos; at = css.find(start, at)) {
    const std::size_t end = css.find(')', at);
    if (end == std::string::npos) break;
    css.replace(at, end + 1 - at, "none");
  }
  return css;
}

// Whether record `index` gets 3D views: measured, and given a scene text.
bool has_views(const std::vector<PartRecord>& records, const std::vector<PartViews>& views, std::size_t index) {
  return !records[index].failed && index < views.size() &&
         (!views[index].nurbs_x3dv.empty() || !views[index].mesh_x3dv.empty());
}

const char* const page_style = R"css(
.note, figcaption { color: #555; font-size: 0.85em; }
.failed li { margin: 0.3em 0; }
.charts, .views { display: flex; flex-wrap: wrap; gap: 1em; }
.charts figure, .views figure { margin: 0; flex: 1 1 480px; min-width: 320px; }
.chart-box { position: relative; height: 320px; border: 1px solid #ddd; }
.view-box { height: 340px; border: 1px solid #ddd; background: #f4f4f4; color: #555; font-size: 0.85em; }
.view-box x3d-canvas { display: block; width: 100%; height: 100%; }
.reference caption { caption-side: top; text-align: left; font-weight: bold; padding: 0.3em 0; }
)css";

// Before X_ITE's script: X_ITE takes the URL of its own <script> as the base of its stylesheet, fonts,
// components and libraries, and an inline script has none (new URL(..., "") throws while X_ITE loads).
// A base under the reserved .invalid domain resolves nothing, so any file the page does not carry fails
// loudly (a console error) instead of reading something that happens to lie beside the page.
const char* const before_x_ite = R"js(
Object.defineProperty(document, 'currentScript', {
  configurable: true,
  get: () => ({ src: 'https://x-ite.invalid/dist/x_ite.min.js' }),
});
)js";

// After it: the real currentScript back; X_ITE's own font faces dropped (they would be fetched when a
// splash screen or menu shows text; the views have neither) so text falls back to the page's font; the
// tangent generator X_ITE fetches for every 3D geometry served from the page.
const char* const after_x_ite_head = R"js(
delete document.currentScript;
for (const face of [...document.fonts])
  if (face.family.includes('X_ITE PT Sans')) document.fonts.delete(face);
{
  const libraryURL = X3D.URLs.getLibraryURL;
  const mikktspace = 'data:application/wasm;base64,)js";
const char* const after_x_ite_tail = R"js(';
  X3D.URLs.getLibraryURL = function (file) {
    return file === 'mikktspace_bg.wasm' ? mikktspace : libraryURL.call(this, file);
  };
}
)js";

// The charts and the 3D views, from the data embedded in the page.
const char* const page_script = R"js(
(() => {
  'use strict';
  const data = (id) => JSON.parse(document.getElementById(id).textContent);
  const report = data('cadnurbs-report-data');
  const scenes = data('cadnurbs-view-data');
  const strong = { nurbs: '#2f6db3', mesh: '#d9822b', nurss: '#3c8f4a', loop: '#3c8f4a' };
  const light = { nurbs: '#9cc0e8', mesh: '#f2c08f', nurss: '#a5d6ad', loop: '#a5d6ad' };
  const curveColours = ['#d9822b', '#b5452f', '#7a8f2b', '#8a5fb0', '#2b8f86'];
  const delivered = (r) => Math.min(r.bytes, r.gzip_bytes);

  // ------------------------------------------------------------------ charts
  function barChart(canvas, part) {
    const reps = part.representations;
    return new Chart(canvas, {
      type: 'bar',
      data: {
        labels: reps.map((r) => r.label),
        datasets: [
          { label: 'file as written', data: reps.map((r) => r.bytes), backgroundColor: reps.map((r) => strong[r.kind]) },
          { label: "gzip'd (level 9)", data: reps.map((r) => r.gzip_bytes), backgroundColor: reps.map((r) => light[r.kind]) },
        ],
      },
      options: {
        indexAxis: 'y', animation: false, responsive: true, maintainAspectRatio: false,
        scales: { x: { type: 'logarithmic', title: { display: true, text: 'bytes (logarithmic)' } } },
      },
    });
  }

  function curveChart(canvas, part) {
    const curves = new Map();
    for (const p of part.curve) {
      if (!curves.has(p.key)) curves.set(p.key, []);
      curves.get(p.key).push({ x: p.deviation, y: delivered(p) });
    }
    const datasets = [...curves].map(([key, points], i) => ({
      label: `${key}, certified mesh at D`,
      data: points.sort((a, b) => a.x - b.x),
      showLine: true,
      borderColor: curveColours[i % curveColours.length],
      backgroundColor: curveColours[i % curveColours.length],
    }));
    // The NURBS file is exact at every D: a level line over the curve's range.
    const nurbs = new Map(part.crossovers.map((c) => [c.nurbs_key, c.nurbs_bytes]));
    if (nurbs.size === 0) {
      const smallest = part.representations.filter((r) => r.kind === 'nurbs')
        .sort((a, b) => delivered(a) - delivered(b))[0];
      if (smallest) nurbs.set(smallest.key, delivered(smallest));
    }
    const ds = part.curve.map((p) => p.deviation);
    const [lo, hi] = [Math.min(...ds), Math.max(...ds)];
    for (const [key, bytes] of nurbs)
      datasets.push({
        label: `${key}, NURBS (exact)`, data: [{ x: lo, y: bytes }, { x: hi, y: bytes }], showLine: true,
        borderDash: [6, 4], pointRadius: 0, borderColor: strong.nurbs, backgroundColor: strong.nurbs,
      });
    return new Chart(canvas, {
      type: 'scatter',
      data: { datasets },
      options: {
        animation: false, responsive: true, maintainAspectRatio: false,
        scales: {
          x: { type: 'logarithmic', title: { display: true, text: `maximum deviation D (${part.unit}, logarithmic)` } },
          y: { type: 'logarithmic', title: { display: true, text: 'bytes delivered (logarithmic)' } },
        },
      },
    });
  }

  for (const canvas of document.querySelectorAll('canvas.bars'))
    barChart(canvas, report.parts[Number(canvas.dataset.part)]);
  for (const canvas of document.querySelectorAll('canvas.curve'))
    curveChart(canvas, report.parts[Number(canvas.dataset.part)]);
  requestAnimationFrame(() => { document.documentElement.dataset.charts = 'ready'; });

  // ------------------------------------------------------------------ 3D views
  // An <x3d-canvas> links X_ITE's stylesheet (beside X_ITE's script) into its shadow root and shows the
  // view once that has loaded: give it the stylesheet the page carries.
  let xIteStylesheet = null;
  function makeCanvas(box) {
    xIteStylesheet ??= 'data:text/css;charset=utf-8,' + encodeURIComponent(data('cadnurbs-x-ite-css'));
    const append = ShadowRoot.prototype.appendChild;
    ShadowRoot.prototype.appendChild = function (node) {
      if (node instanceof HTMLLinkElement && node.rel === 'stylesheet') {
        node.removeAttribute('integrity');
        node.removeAttribute('crossorigin');
        node.href = xIteStylesheet;
      }
      return append.call(this, node);
    };
    try {
      box.innerHTML = '<x3d-canvas splashScreen="false" notifications="false" contextMenu="false" timings="false"></x3d-canvas>';
    } finally {
      ShadowRoot.prototype.appendChild = append;
    }
    return box.firstElementChild;
  }

  // X_ITE imports a component a scene names from beside its script; the page has already run the NURBS
  // component, so this browser is told it is built in. (updateSupportedComponent fails in X_ITE 15.0.1.)
  function useInlinedNurbs(browser) {
    const c = browser.getSupportedComponent('NURBS');
    browser.removeSupportedComponent('NURBS');
    browser.addSupportedComponent(new X3D.ComponentInfo(c.name, c.level, c.title, c.providerURL, false, [...(c.dependencies ?? [])]));
  }

  const maxLiveViews = 8;  // a page gets about 16 WebGL contexts before the browser drops the oldest
  const live = [];         // boxes holding a view, oldest first
  const visible = new Set();

  function release(box) {
    const canvas = box.querySelector('x3d-canvas');
    if (canvas) X3D.getBrowser(canvas).dispose();
    box.replaceChildren();
    box.dataset.state = 'released';
    live.splice(live.indexOf(box), 1);
  }

  function makeRoom() {
    while (live.length >= maxLiveViews) {
      const settled = live.filter((b) => b.dataset.state !== 'loading');
      const victim = settled.find((b) => !visible.has(b.closest('.views'))) ?? settled[0];
      if (!victim) return;
      release(victim);
    }
  }

  async function show(box) {
    if (['loading', 'ready', 'failed'].includes(box.dataset.state)) return;
    makeRoom();
    box.dataset.state = 'loading';
    live.push(box);
    const part = Number(box.dataset.part), kind = box.dataset.view;
    try {
      const browser = X3D.getBrowser(makeCanvas(box));
      useInlinedNurbs(browser);
      browser.setBrowserOption('StraightenHorizon', false);  // keep the file's Viewpoint as written
      const scene = await browser.createX3DFromString(scenes[part][kind]);
      if (!scene.rootNodes.some((n) => n?.getNodeTypeName?.() === 'Background')) {
        const background = scene.createNode('Background');
        background.skyColor = new X3D.MFColor(new X3D.SFColor(0.957, 0.957, 0.957));
        scene.rootNodes.push(background);
      }
      await browser.replaceWorld(scene);
      await browser.nextFrame();
      box.dataset.state = 'ready';
    } catch (error) {
      box.replaceChildren();
      box.dataset.state = 'failed';
      const message = `${report.parts[part].input}: ${kind} view: ${error?.message ?? error}`;
      box.textContent = `Could not draw: ${message}`;
      console.error(`cadnurbs report: ${message}`);
    }
  }

  const observer = new IntersectionObserver((entries) => {
    for (const entry of entries) {
      if (entry.isIntersecting) {
        visible.add(entry.target);
        for (const box of entry.target.querySelectorAll('.view-box')) show(box);
      } else {
        visible.delete(entry.target);
      }
    }
  }, { rootMargin: '300px' });
  for (const views of document.querySelectorAll('.views')) observer.observe(views);
})();
)js";

std::string summary_table(const std::vector<PartRecord>& records) {
  std::ostringstream out;
  out << "<section id=\"summary\"><h2>Parts</h2>\n<table class=\"summary\"><thead><tr><th>part</th><th>D</th>"
         "<th>NURBS floats</th><th>trim floats</th><th>mesh floats at D</th><th>smallest NURBS file</th>"
         "<th>bytes</th><th>smallest mesh file</th><th>bytes</th><th>mesh / NURBS</th></tr></thead><tbody>\n";
  for (std::size_t i = 0; i < records.size(); ++i) {
    const auto& r = records[i];
    if (r.failed) continue;
    const auto* nurbs = smallest_representation(r, RepresentationKind::nurbs);
    const auto* mesh = smallest_representation(r, RepresentationKind::mesh);
    out << "<tr><td><a href=\"#part-" << i << "\">" << escape_html(r.input) << "</a></td><td class=\"n\">"
        << report_number(r.deviation) << " " << escape_html(r.unit) << "</td><td class=\"n\">" << grouped(r.nurbs.floats)
        << "</td><td class=\"n\">" << grouped(r.nurbs.trim_floats) << "</td><td class=\"n\">"
        << grouped(r.mesh.indexed_floats) << "</td><td>" << (nurbs ? escape_html(nurbs->label) : "-")
        << "</td><td class=\"n\">" << (nurbs ? grouped(delivered_bytes(*nurbs)) : "-") << "</td><td>"
        << (mesh ? escape_html(mesh->label) : "-") << "</td><td class=\"n\">"
        << (mesh ? grouped(delivered_bytes(*mesh)) : "-") << "</td><td class=\"n\">"
        << (nurbs && mesh && delivered_bytes(*nurbs) > 0
                ? report_number(double(delivered_bytes(*mesh)) / double(delivered_bytes(*nurbs)), 3)
                : "-")
        << "</td></tr>\n";
  }
  out << "</tbody></table>\n<p class=\"note\">Smallest file: the smaller of the file and its gzip'd form, over "
         "every representation of that kind.</p></section>\n";
  return out.str();
}

std::string failed_list(const std::vector<PartRecord>& records) {
  const auto failed = std::count_if(records.begin(), records.end(), [](const PartRecord& r) { return r.failed; });
  if (failed == 0) return "";
  std::ostringstream out;
  out << "<section id=\"failed\" class=\"failed\"><h2>Failed inputs (" << failed << ")</h2>\n<ul>\n";
  for (const auto& r : records)
    if (r.failed) out << "<li><code>" << escape_html(r.input) << "</code>: " << escape_html(r.error) << "</li>\n";
  out << "</ul></section>\n";
  return out.str();
}

std::string crossover_sentences(const PartRecord& r) {
  std::ostringstream out;
  for (const auto& c : r.crossovers) {
    out << "<p>" << escape_html(c.mesh_key) << " against " << escape_html(c.nurbs_key) << " (" << grouped(c.nurbs_bytes)
        << " bytes): ";
    if (!std::isnan(c.deviation))
      out << "the mesh costs more below D = " << report_number(c.deviation, 3) << " " << escape_html(r.unit) << ".";
    else if (c.mesh_larger_everywhere)
      out << "the mesh costs more at every D measured.";
    else
      out << "the mesh costs less at every D measured.";
    out << "</p>\n";
  }
  return out.str();
}

std::string view_figure(std::size_t index, const char* kind, const std::string& caption) {
  std::ostringstream out;
  out << "<figure class=\"view\"><div class=\"view-box\" data-part=\"" << index << "\" data-view=\"" << kind
      << "\" data-state=\"waiting\"></div><figcaption>" << caption << "</figcaption></figure>\n";
  return out.str();
}

std::string part_section(const std::vector<PartRecord>& records, std::size_t index, const std::vector<PartViews>& views) {
  const PartRecord& r = records[index];
  std::ostringstream out;
  out << "<section class=\"part\" id=\"part-" << index << "\"><h2>" << escape_html(r.input) << "</h2>\n<p>Maximum deviation D = "
      << report_number(r.deviation) << " " << escape_html(r.unit) << " (bounding-box diagonal " << report_number(r.diagonal) << " "
      << escape_html(r.unit) << "). NURBS: " << r.nurbs.surfaces << " surfaces, " << grouped(r.nurbs.control_points)
      << " control points, " << grouped(r.nurbs.knots) << " knots; compact form "
      << grouped(r.compact_nurbs.control_points) << " control points, " << grouped(r.compact_nurbs.knots) << " knots, "
      << grouped(r.compact_nurbs.polygon_vertices) << " polygon vertices. Mesh at D: " << grouped(r.mesh.vertices)
      << " vertices, " << grouped(r.mesh.triangles) << " triangles (certified " << report_number(r.mesh_certified_deviation)
      << ").</p>\n<div class=\"charts\">\n<figure class=\"chart\"><div class=\"chart-box\"><canvas class=\"bars\" "
         "data-part=\""
      << index << "\" role=\"img\" aria-label=\"bytes per representation\"></canvas></div><figcaption>Bytes of every "
                  "file written and read back: dark, as written; light, gzip'd at level 9. Blue: NURBS; orange: "
                  "mesh; green: subdivision control mesh.</figcaption></figure>\n";
  if (!r.curve.empty())
    out << "<figure class=\"chart\"><div class=\"chart-box\"><canvas class=\"curve\" data-part=\"" << index
        << "\" role=\"img\" aria-label=\"storage against deviation\"></canvas></div><figcaption>Storage against "
           "accuracy: the certified mesh at each maximum deviation D (bytes delivered, the smaller of the file and "
           "its gzip'd form) and the smallest NURBS file, which is exact at every D.</figcaption></figure>\n";
  out << "</div>\n" << crossover_sentences(r);
  if (has_views(records, views, index)) {
    out << "<div class=\"views\" data-part=\"" << index << "\">\n";
    if (!views[index].nurbs_x3dv.empty())
      out << view_figure(index, "nurbs", "As NURBS: the X3D file as written, tessellated by X_ITE.");
    if (!views[index].mesh_x3dv.empty())
      out << view_figure(index, "mesh", "As mesh: the triangles a mesh viewer is given.");
    out << "</div>\n";
  }
  out << "<table class=\"representations\"><thead><tr><th>representation</th><th>bytes</th><th>gzip'd</th>"
         "<th>floats</th><th>integers</th><th>deviation</th><th>how the deviation is known</th></tr></thead><tbody>\n";
  for (const auto& f : r.representations)
    out << "<tr><td>" << escape_html(f.label) << "</td><td class=\"n\">" << grouped(f.bytes) << "</td><td class=\"n\">"
        << grouped(f.gzip_bytes) << "</td><td class=\"n\">" << grouped(f.floats) << "</td><td class=\"n\">"
        << grouped(f.integers) << "</td><td class=\"n\">" << labelled_deviation(f) << "</td><td>"
        << escape_html(f.deviation_basis) << "</td></tr>\n";
  out << "</tbody></table>\n";
  if (!r.warnings.empty()) {
    out << "<p>Reader's notes:</p><ul>\n";
    for (const auto& w : r.warnings) out << "<li>" << escape_html(w) << "</li>\n";
    out << "</ul>\n";
  }
  out << "</section>\n";
  return out.str();
}

std::string reference_table() {
  std::ostringstream out;
  out << "<section id=\"reference\"><h2>Reference figures: the papers' own, not measured here</h2>\n"
         "<table class=\"reference\"><caption>The papers' figures (seed documents), for comparison with the "
         "measured ones above</caption><thead><tr><th>source</th><th>part</th><th>quantity</th><th>value</th>"
         "</tr></thead><tbody>\n";
  for (const auto& f : reference_figures())
    out << "<tr><td>" << escape_html(f.source) << "</td><td>" << escape_html(f.part) << "</td><td>"
        << escape_html(f.quantity) << "</td><td>" << escape_html(f.value) << "</td></tr>\n";
  out << "</tbody></table></section>\n";
  return out.str();
}

// [ {"nurbs": text, "mesh": text} | null, ... ], one entry per record.
std::string view_data(const std::vector<PartRecord>& records, const std::vector<PartViews>& views) {
  std::string out = "[";
  for (std::size_t i = 0; i < records.size(); ++i) {
    if (i > 0) out += ",\n";
    if (!has_views(records, views, i))
      out += "null";
    else
      out += "{\"nurbs\": " + json_string(views[i].nurbs_x3dv) + ", \"mesh\": " + json_string(views[i].mesh_x3dv) + "}";
  }
  return out + "]";
}

}  // namespace

std::string report_html(const std::vector<PartRecord>& records, const std::vector<PartViews>& views) {
  if (!views.empty() && views.size() != records.size())
    throw std::invalid_argument("report_html: " + std::to_string(views.size()) + " views for " +
                                std::to_string(records.size()) + " records (one per record, or none)");
  bool any_view = false;
  for (std::size_t i = 0; i < records.size(); ++i) any_view = any_view || has_views(records, views, i);

  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
         "<meta name=\"generator\" content=\"cadnurbs\">\n<title>cadnurbs storage report</title>\n<style>"
      << base_page_style << page_style << "</style>\n<script>" << inline_script("chart.umd.min.js") << "</script>\n";
  if (any_view)
    out << "<script>" << before_x_ite << "</script>\n<script>" << inline_script("x_ite.min.js") << "</script>\n<script>"
        << after_x_ite_head << base64(report_html_asset("mikktspace_bg.wasm")) << after_x_ite_tail
        << "</script>\n<script>{\n" << inline_script("NURBSComponent.min.js") << "\n}</script>\n";
  out << "</head><body>\n<header><h1>cadnurbs storage report</h1>\n<p class=\"accounting\">"
      << escape_html(accounting_rule()) << "</p></header>\n"
      << summary_table(records) << failed_list(records);
  for (std::size_t i = 0; i < records.size(); ++i)
    if (!records[i].failed) out << part_section(records, i, views);
  out << reference_table() << "<footer><p>Made by cadnurbs with " << escape_html(report_html_asset("versions"))
      << ", inlined.</p><details><summary>Licences of the inlined software</summary><pre>"
      << escape_html(report_html_asset("licenses")) << "</pre></details></footer>\n"
      << "<script type=\"application/json\" id=\"cadnurbs-report-data\">" << script_json(report_json(records))
      << "</script>\n<script type=\"application/json\" id=\"cadnurbs-view-data\">"
      << script_json(view_data(records, views)) << "</script>\n";
  if (any_view)
    out << "<script type=\"application/json\" id=\"cadnurbs-x-ite-css\">" << script_json(json_string(x_ite_stylesheet()))
        << "</script>\n";
  out << "<script>" << page_script << "</script>\n</body></html>\n";
  return out.str();
}

}  // namespace cadnurbs
