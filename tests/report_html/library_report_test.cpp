// The library-wide report of `cadnurbs batch`: the sums, ratio bins and failure reasons of
// summarise_library on records whose answers are known, and the page library_report_html makes of them
// (counts shown, every record text escaped, the chart data parsing back to the summary).
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "report/html/library_report_html.hpp"
#include "report/library_summary.hpp"

namespace cadnurbs {
namespace {

RepresentationFigures figures(const std::string& key, RepresentationKind kind, long bytes, long gzip_bytes) {
  RepresentationFigures f;
  f.key = key;
  f.label = key + " label";
  f.kind = kind;
  f.bytes = bytes;
  f.gzip_bytes = gzip_bytes;
  return f;
}

// A measured part whose smallest NURBS delivery is `nurbs` bytes and smallest mesh delivery `mesh` bytes.
PartRecord part(const std::string& input, long nurbs, long mesh) {
  PartRecord r;
  r.input = input;
  r.unit = "mm";
  r.deviation = 0.01;
  r.representations = {figures("x3dv-compact", RepresentationKind::nurbs, 4 * nurbs, nurbs),
                       figures("wrl-mesh", RepresentationKind::mesh, 3 * mesh, mesh),
                       figures("stl-mesh", RepresentationKind::mesh, 5 * mesh, 2 * mesh)};
  return r;
}

PartRecord failed(const std::string& input, const std::string& error) {
  PartRecord r;
  r.input = input;
  r.failed = true;
  r.error = error;
  return r;
}

std::vector<PartRecord> library() {
  PartRecord loop = part("stl/bracket.stl", 0, 800);
  loop.representations[0] = figures("loop", RepresentationKind::loop, 300, 100);  // ratio 1/8
  return {part("a.step", 100, 1000),   // 0.1: bin [1/16, 1/8)
          part("b.step", 260, 1000),   // 0.26: bin [1/4, 1/2)
          part("c.step", 3000, 1000),  // 3: bin [2, 4)
          loop,
          failed("d.step", "exceeded 300 s"),
          failed("e.wrl", "line 278: unsupported node CoordinateInterpolator (outside the VRML97 subset cadnurbs reads)"),
          failed("f.wrl", "line 12: unsupported node CoordinateInterpolator (outside the VRML97 subset cadnurbs reads)"),
          failed("g.iges", "entity #14: rational B-spline surface with 2 weights for 9 poles")};
}

TEST(LibraryReport, FailureReasonsDropPlacesNumbersAndAsides) {
  EXPECT_EQ(failure_reason("exceeded 300 s"), "exceeded N s");
  EXPECT_EQ(failure_reason("line 278: unsupported node CoordinateInterpolator (outside the VRML97 subset)"),
            "unsupported node CoordinateInterpolator");
  EXPECT_EQ(failure_reason("entity #14: rational B-spline surface with 2 weights for 9 poles"),
            "rational B-spline surface with N weights for N poles");
  EXPECT_EQ(failure_reason("object 3 (ON_Brep): no faces"), "no faces");
  EXPECT_EQ(failure_reason("crashed with SIGSEGV"), "crashed with SIGSEGV");
  EXPECT_EQ(failure_reason("/tmp/cadnurbs-report-28009-0/v5-compact.wrl: the NURBS PROTO library has no PROTO NurbsCurve"),
            "the NURBS PROTO library has no PROTO NurbsCurve");
  EXPECT_EQ(failure_reason("scene/node 0/shape 0: trimming loop 0 leaves the surface's domain by 10 of its size"),
            "trimming loop N leaves the surface's domain by N of its size");
  EXPECT_EQ(failure_reason("part.wrl: no shape"), "no shape");
  EXPECT_EQ(failure_reason("STEP reader: no shape in the file"), "STEP reader: no shape in the file");
  EXPECT_EQ(failure_reason("(only an aside)"), "(only an aside)");
}

TEST(LibraryReport, SummarySumsEveryRepresentationBinsRatiosAndGroupsFailures) {
  const LibrarySummary s = summarise_library(library());
  EXPECT_EQ(s.parts, 8);
  EXPECT_EQ(s.measured, 4);
  EXPECT_EQ(s.failed, 4);
  ASSERT_EQ(s.totals.size(), 4u);  // x3dv-compact, wrl-mesh, stl-mesh in first-seen order, then loop
  EXPECT_EQ(s.totals[0].key, "x3dv-compact");
  EXPECT_EQ(s.totals[0].parts, 3);
  EXPECT_EQ(s.totals[0].bytes, 4 * (100 + 260 + 3000));
  EXPECT_EQ(s.totals[0].gzip_bytes, 100 + 260 + 3000);
  EXPECT_EQ(s.totals[1].key, "wrl-mesh");
  EXPECT_EQ(s.totals[1].parts, 4);
  EXPECT_EQ(s.totals[1].gzip_bytes, 1000 + 1000 + 1000 + 800);
  EXPECT_EQ(s.totals[3].key, "loop");
  EXPECT_EQ(s.totals[3].bytes, 300);
  EXPECT_EQ(s.ratio_parts, 4);
  EXPECT_EQ(s.smaller_than_mesh, 3);
  ASSERT_EQ(s.ratio_bins.size(), 12u);  // below 1/256, ten powers of 2 up to 4, from 4 on
  EXPECT_EQ(s.ratio_bins.front().low, 0);
  EXPECT_EQ(s.ratio_bins.front().high, 1.0 / 256);
  EXPECT_TRUE(std::isinf(s.ratio_bins.back().high));
  std::vector<int> counts;
  for (const auto& b : s.ratio_bins) counts.push_back(b.parts);
  //                                <  1/256 1/128 1/64 1/32 1/16 1/8 1/4 1/2  1   2   4
  EXPECT_EQ(counts, (std::vector<int>{0, 0, 0, 0, 0, 1, 1, 1, 0, 0, 1, 0}));
  ASSERT_EQ(s.failures.size(), 3u);
  EXPECT_EQ(s.failures[0].reason, "unsupported node CoordinateInterpolator");
  EXPECT_EQ(s.failures[0].parts, (std::vector<std::string>{"e.wrl", "f.wrl"}));
  EXPECT_EQ(s.failures[1].reason, "exceeded N s");
  EXPECT_EQ(s.failures[2].reason, "rational B-spline surface with N weights for N poles");
}

TEST(LibraryReport, PageShowsTheCountsEscapesRecordTextAndCarriesTheChartData) {
  std::vector<PartRecord> records = library();
  records.push_back(failed("evil</script><script>alert(1)</script>.step", "line 1: <b>bad</b>"));
  const std::string page = library_report_html(records);
  EXPECT_NE(page.find("<p>9 parts: 4 converted and measured, 5 failed.</p>"), std::string::npos);
  EXPECT_NE(page.find("3 of 4 parts compared have a smooth file smaller"), std::string::npos);
  EXPECT_EQ(page.find("<script>alert(1)"), std::string::npos);
  EXPECT_EQ(page.find("<b>bad</b>"), std::string::npos);
  EXPECT_NE(page.find("evil&lt;/script&gt;&lt;script&gt;alert(1)&lt;/script&gt;.step"), std::string::npos);
  const std::string open = "<script type=\"application/json\" id=\"cadnurbs-library-data\">";
  const size_t start = page.find(open);
  ASSERT_NE(start, std::string::npos);
  const size_t end = page.find("</script>", start);
  const auto data = nlohmann::json::parse(page.substr(start + open.size(), end - start - open.size()));
  ASSERT_EQ(data["ratio_bins"].size(), 12u);
  EXPECT_EQ(data["ratio_bins"][5]["label"], "1/16\u20131/8");
  EXPECT_EQ(data["ratio_bins"][5]["parts"], 1);
  ASSERT_EQ(data["failures"].size(), 4u);
  EXPECT_EQ(data["failures"][0]["parts"], 2);
  EXPECT_EQ(data["failures"][1]["reason"], "<b>bad</b>");  // ties by reason; as data, parsed back; never markup
  EXPECT_EQ(data["totals"][0]["gzip_bytes"], 3360);
  EXPECT_EQ(data["totals"][3]["kind"], "loop");
}

}  // namespace
}  // namespace cadnurbs
