// convert --simplify D on a real part: fewer control points, a certified deviation within D, and the
// mesh at D as watertight as the input's (issue 15).
#include <regex>

#include "command_fixture.hpp"

namespace cadnurbs::test {
namespace {

class Simplify : public CommandTest {};

TEST_F(Simplify, CorpusPartLosesControlPointsWithinTheCertifiedDeviation) {
  // CAx-IF dm1: B-spline faces (rational quadratic sweeps) with knots their shape does not need.
  const std::string step = std::string(CADNURBS_SHARED_DIR) + "/corpus/step/dm1-id-214.stp";
  const double d = 0.15;  // 0.001 x its bounding-box diagonal (146 mm), rounded up
  const CommandResult r = run("convert " + step + " -o " + path("dm1.x3dv") + " --simplify 0.15");
  ASSERT_EQ(r.status, 0) << r.err;
  std::smatch m;
  const std::regex summary(
      R"(simplified within 0\.15 mm \(faces moved by at most (\S+), \d attempts?\): (\d+) knots removed .*control points )"
      R"((\d+) -> (\d+), certified deviation (\S+) mm .*meshed at 0\.15: (\d+) open edges \S+ \S+ before, (\d+) open )"
      R"(edges \S+ \S+ after, 0 unshared edge uses)");
  ASSERT_TRUE(std::regex_search(r.out, m, summary)) << r.out;
  EXPECT_LE(std::stod(m[1]), d / 8);
  EXPECT_GT(std::stol(m[2]), 0);
  EXPECT_LT(std::stol(m[4]), std::stol(m[3]));
  EXPECT_GT(std::stod(m[5]), 0.0);  // measured, not assumed
  EXPECT_LE(std::stod(m[5]), d);
  EXPECT_EQ(m[6], "0");  // the B-rep is closed, and so is the simplified part's mesh
  EXPECT_EQ(m[7], "0");
  // As many faces and polygon sets as the plain conversion writes, and the file written reads back.
  const CommandResult plain = run("convert " + step + " -o " + path("plain.x3dv"));
  ASSERT_EQ(plain.status, 0) << plain.err;
  const std::regex written(R"(x3dv: (\d+) NURBS surfaces, (\d+) polygon sets)");
  std::smatch a, b;
  ASSERT_TRUE(std::regex_search(plain.out, a, written)) << plain.out;
  ASSERT_TRUE(std::regex_search(r.out, b, written)) << r.out;
  EXPECT_EQ(a[1], b[1]);
  EXPECT_EQ(a[2], b[2]);
  const CommandResult info = run("info " + path("dm1.x3dv"));
  ASSERT_EQ(info.status, 0) << info.err;
  EXPECT_NE(info.out.find("trimmed NURBS surface"), std::string::npos) << info.out;
}

TEST_F(Simplify, RefusesMeshOutputAndNonPositiveDistances) {
  const std::string step = std::string(CADNURBS_SHARED_DIR) + "/corpus/step/screw.step";
  CommandResult r = run("convert " + step + " -o " + path("s.stl") + " --simplify 0.1");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("--simplify applies to NURBS output only"), std::string::npos) << r.err;
  r = run("convert " + step + " -o " + path("s.x3dv") + " --simplify 0");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("--simplify must be positive"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(path("s.x3dv")));
}

}  // namespace
}  // namespace cadnurbs::test
