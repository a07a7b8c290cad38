// convert --simplify D on a real part: fewer control points, a certified deviation within D, and the
// mesh at D as watertight as the input's (issue 15).
#include <filesystem>
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
      R"(simplified within 0\.15 mm \(faces moved by at most (\S+), \d attempts?; \d+ repeated parts placed as copies first\): )"
      R"((\d+) knots removed .*control points )"
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
  // Without display hints (a face with fewer control points may need one the source did not), the
  // simplified file is the smaller one.
  ASSERT_EQ(run("convert " + step + " -o " + path("plain-bare.x3dv") + " --display-deviation 0").status, 0);
  ASSERT_EQ(run("convert " + step + " -o " + path("dm1-bare.x3dv") + " --display-deviation 0 --simplify 0.15").status, 0);
  EXPECT_LT(std::filesystem::file_size(path("dm1-bare.x3dv")), std::filesystem::file_size(path("plain-bare.x3dv")));
  const CommandResult info = run("info " + path("dm1.x3dv"));
  ASSERT_EQ(info.status, 0) << info.err;
  EXPECT_NE(info.out.find("trimmed NURBS surface"), std::string::npos) << info.out;
}

// hammer.iges holds one face twice up to a rigid motion, its parameters reversed in the copy. Simplified
// copy by copy, the two lost different knots and were written apart (65,250 -> 65,936 bytes); placed as
// copies first, they lose the same knots and the file is written with its USE, smaller than the plain one.
TEST_F(Simplify, RepeatedPartsStayCopies) {
  const std::string iges = std::string(CADNURBS_SHARED_DIR) + "/corpus/iges/hammer.iges";
  const CommandResult plain = run("convert " + iges + " -o " + path("plain.x3dv"));
  ASSERT_EQ(plain.status, 0) << plain.err;
  const CommandResult r = run("convert " + iges + " -o " + path("simpler.x3dv") + " --simplify 41.4");
  ASSERT_EQ(r.status, 0) << r.err;
  std::smatch placed, knots;
  ASSERT_TRUE(std::regex_search(plain.out, placed, std::regex(R"((\d+) repeated parts placed as copies\n)"))) << plain.out;
  EXPECT_GT(std::stoi(placed[1]), 0);
  EXPECT_NE(r.out.find("; " + placed[1].str() + " repeated parts placed as copies first)"), std::string::npos) << r.out;
  ASSERT_TRUE(std::regex_search(r.out, knots, std::regex(R"(: (\d+) knots removed)"))) << r.out;
  EXPECT_GT(std::stoi(knots[1]), 0);
  const auto uses = [&](const std::string& file) {
    const std::string text = read_file(path(file));
    long n = 0;
    for (size_t at = text.find(" USE "); at != std::string::npos; at = text.find(" USE ", at + 1)) ++n;
    return n;
  };
  EXPECT_EQ(uses("simpler.x3dv"), uses("plain.x3dv"));
  EXPECT_LT(std::filesystem::file_size(path("simpler.x3dv")), std::filesystem::file_size(path("plain.x3dv")));
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
