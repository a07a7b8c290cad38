// The HTML report's page: what it lists, one chart per measured part, and that no embedded text can end
// a <script> element (the embedded data parse back to what was put in).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "report/reference_figures.hpp"
#include "report/report_formats.hpp"
#include "report/html/report_html.hpp"

namespace cadnurbs {
namespace {

const std::string hostile_input = "parts/evil</script><script>alert(1)</script><!--.step";
const std::string hostile_scene = "#X3D V3.3 utf8\nPROFILE Interchange\nWorldInfo { info [\"</SCRIPT><!-- <script>\"] }\n";

RepresentationFigures figures(const std::string& key, const std::string& label, RepresentationKind kind, long bytes,
                              long gzip_bytes) {
  RepresentationFigures f;
  f.key = key;
  f.label = label;
  f.kind = kind;
  f.bytes = bytes;
  f.gzip_bytes = gzip_bytes;
  return f;
}

PartRecord measured_record(const std::string& input, bool with_curve) {
  PartRecord r;
  r.input = input;
  r.unit = "mm";
  r.diagonal = 210.5;
  r.deviation = 1;
  r.nurbs.surfaces = 9;
  r.nurbs.control_points = 155;
  r.nurbs.knots = 48;
  r.nurbs.floats = 4 * 155 + 48;
  r.mesh.vertices = 144;
  r.mesh.indexed_floats = 3 * 144;
  r.representations = {figures("x3dv-compact", "X3D classic NURBS, compact", RepresentationKind::nurbs, 6100, 1700),
                       figures("wrl-mesh", "VRML97 IndexedFaceSet at D", RepresentationKind::mesh, 9800, 2900)};
  if (with_curve) {
    r.curve = {{"wrl-mesh", 2.0, 5000, 1600, 300}, {"wrl-mesh", 0.5, 31000, 9000, 2000}};
    r.crossovers = {{"wrl-mesh", "x3dv-compact", 1700, 1.4, false}};
  }
  return r;
}

PartRecord failed_record() {
  PartRecord r;
  r.input = "library/broken-bracket.step";
  r.failed = true;
  r.error = "library/broken-bracket.step: STEP reader: no shape in the file";
  return r;
}

std::size_t count(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (std::size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + needle.size())) ++n;
  return n;
}

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return text;
}

// The text of the <script> element with this id: up to the first "</script" after its start tag, as an
// HTML parser ends it.
std::string script_element_text(const std::string& page, const std::string& id) {
  const std::string start = "id=\"" + id + "\">";
  const std::size_t begin = page.find(start);
  if (begin == std::string::npos) throw std::runtime_error("no element " + id);
  const std::size_t content = begin + start.size();
  const std::size_t end = lower(page).find("</script", content);
  return page.substr(content, end - content);
}

TEST(ReportHtml, ListsTheFailedInputWithItsReason) {
  const std::string page = report_html({measured_record("capping-90.step", false), failed_record()});
  EXPECT_NE(page.find("Failed inputs (1)"), std::string::npos);
  EXPECT_NE(page.find("<code>library/broken-bracket.step</code>: library/broken-bracket.step: STEP reader: no shape in "
                      "the file"),
            std::string::npos);
}

TEST(ReportHtml, CarriesTheAccountingRuleAndThePapersFiguresLabelledAsTheirs) {
  const std::string page = report_html({measured_record("capping-90.step", false), failed_record()});
  EXPECT_NE(page.find("Reference figures: the papers' own, not measured here"), std::string::npos);
  ASSERT_EQ(reference_figures().size(), 5u);
  for (const auto& f : reference_figures()) EXPECT_NE(page.find("<td>" + f.value + "</td>"), std::string::npos) << f.value;
  EXPECT_NE(page.find("2,468 floats"), std::string::npos);
  EXPECT_NE(page.find("66 KB / 7 KB"), std::string::npos);
  EXPECT_NE(page.find(accounting_rule().substr(0, 60)), std::string::npos);
}

TEST(ReportHtml, OneBarChartPerMeasuredPartAndACurveChartWhereThereIsACurve) {
  const std::string page = report_html(
      {measured_record("a.step", true), failed_record(), measured_record("b.step", false), measured_record("c.step", true)});
  EXPECT_EQ(count(page, "<canvas class=\"bars\""), 3u);
  EXPECT_EQ(count(page, "<canvas class=\"curve\""), 2u);
  EXPECT_NE(page.find("<canvas class=\"bars\" data-part=\"2\""), std::string::npos);  // indices of report_json's parts
  EXPECT_EQ(page.find("<canvas class=\"bars\" data-part=\"1\""), std::string::npos);  // the failed one
  EXPECT_NE(page.find("the mesh costs more below D = 1.4 mm."), std::string::npos);
}

TEST(ReportHtml, NoEmbeddedTextEndsAScriptElement) {
  const std::vector<PartRecord> records{measured_record(hostile_input, true), failed_record()};
  const std::string page = report_html(records, {{hostile_scene, hostile_scene}, {}});
  const std::string folded = lower(page);
  // Every <script> start tag has exactly its own end tag, and the hostile text appears only escaped.
  EXPECT_EQ(count(folded, "<script>") + count(folded, "<script type="), count(folded, "</script"));
  EXPECT_EQ(page.find("evil</script>"), std::string::npos);
  EXPECT_EQ(folded.find("</script><!--"), std::string::npos);
  EXPECT_NE(page.find("parts/evil&lt;/script&gt;&lt;script&gt;alert(1)&lt;/script&gt;&lt;!--.step"), std::string::npos);
  // What the page's script reads back is exactly what was given.
  const auto report = nlohmann::json::parse(script_element_text(page, "cadnurbs-report-data"));
  EXPECT_EQ(report["parts"][0]["input"], hostile_input);
  EXPECT_EQ(report["parts"][1]["error"], records[1].error);
  const auto views = nlohmann::json::parse(script_element_text(page, "cadnurbs-view-data"));
  ASSERT_EQ(views.size(), 2u);
  EXPECT_EQ(views[0]["nurbs"], hostile_scene);
  EXPECT_EQ(views[0]["mesh"], hostile_scene);
  EXPECT_TRUE(views[1].is_null());
}

TEST(ReportHtml, ViewsOnlyForPartsGivenAScene) {
  const std::vector<PartRecord> records{measured_record("a.step", false), failed_record(), measured_record("b.step", false)};
  const std::string with_views = report_html(records, {{"nurbs a", "mesh a"}, {"nurbs of a failed part", ""}, {"", ""}});
  EXPECT_EQ(count(with_views, "class=\"view-box\""), 2u);
  EXPECT_NE(with_views.find("data-part=\"0\" data-view=\"nurbs\""), std::string::npos);
  EXPECT_NE(with_views.find("data-part=\"0\" data-view=\"mesh\""), std::string::npos);
  EXPECT_EQ(with_views.find("nurbs of a failed part"), std::string::npos);
  EXPECT_NE(with_views.find("X_ITE v15"), std::string::npos);  // the 3D viewer is inlined...
  const std::string without_views = report_html(records);
  EXPECT_EQ(count(without_views, "class=\"view-box\""), 0u);
  EXPECT_EQ(without_views.find("X_ITE v15"), std::string::npos);  // ...only when there is something to show
  EXPECT_NE(without_views.find("Chart.js v4"), std::string::npos);
  EXPECT_LT(without_views.size() + 1000000, with_views.size());
}

TEST(ReportHtml, RefusesViewsThatDoNotMatchTheRecords) {
  try {
    report_html({measured_record("a.step", false), failed_record()}, {{"nurbs", "mesh"}});
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "report_html: 1 views for 2 records (one per record, or none)");
  }
}

}  // namespace
}  // namespace cadnurbs
