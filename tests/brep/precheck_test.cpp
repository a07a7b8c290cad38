// The STEP and IGES pre-checks (issue 13): corpus files changed the way the hostile-input run found OCCT
// crashing or hanging on (100,000 nested parentheses, inf, NaN, a 30-digit integer, a 1,000,000-item list)
// and other damage (a dangling reference, an unterminated string; IGES Terminate counts, a directory
// pointer past the Parameter Data section, a number too large for a double), each refused with its exact
// message by the pre-check and by read_step / read_iges before OCCT sees the file: without the check
// these tests would crash or hang. Every corpus file passes.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "corpus_manifest.hpp"
#include "formats/common/file_io.hpp"
#include "formats/iges/iges_precheck.hpp"
#include "formats/iges/iges_reader.hpp"
#include "formats/step/step_precheck.hpp"
#include "formats/step/step_reader.hpp"
#include "temporary_folder.hpp"

namespace cadnurbs::test {
namespace {

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out << bytes;
}

// `text` with its one occurrence of `from` replaced by `to`.
std::string replaced(const std::string& text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  EXPECT_EQ(text.find(from, at + 1), std::string::npos) << from << " occurs twice";
  if (at == std::string::npos) return text;
  return text.substr(0, at) + to + text.substr(at + from.size());
}

// The 1-based line on which `needle` starts in `text`.
int line_of(const std::string& text, const std::string& needle) {
  const size_t at = text.find(needle);
  EXPECT_NE(at, std::string::npos) << needle;
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

template <class Read>
std::string error_of(const Read& read) {
  try {
    read();
  } catch (const FileError& error) {
    return error.what();
  }
  return "(no error)";
}

// screw.step: small, and its #19/#20 are a vertex and its point.
class StepPrecheck : public ::testing::Test {
 protected:
  // Writes `bytes` as a .step file and returns the message both the pre-check and read_step give.
  std::string refusal(const std::string& bytes) {
    const std::string path = folder_.file("damaged.step");
    write_bytes(path, bytes);
    const std::string message = error_of([&] { precheck_step_file(path); });
    EXPECT_EQ(error_of([&] { read_step(path); }), message);
    return message;
  }
  std::string path() const { return folder_.file("damaged.step"); }

  const std::string original_ = read_file(corpus_file("step/screw.step"));
  const std::string point_ = "#20 = CARTESIAN_POINT('',(-27.8196811084,0.423702927757,5.43633));";
  const int point_line_ = line_of(original_, point_);
  TemporaryFolder folder_;
};

TEST_F(StepPrecheck, DeepNestingIsRefusedWithItsDepth) {
  // 100,000 parentheses deep in all (OCCT's recursive parser overflows its stack).
  const std::string deep = "#20 = CARTESIAN_POINT(''," + std::string(99999, '(') + "0." + std::string(99999, ')') + ");";
  EXPECT_EQ(refusal(replaced(original_, point_, deep)),
            path() + ": line " + std::to_string(point_line_) +
                ", #20 CARTESIAN_POINT: parentheses nested 100000 deep (the limit is 64)");
}

TEST_F(StepPrecheck, NonFiniteAndOverflowingNumbersAreRefused) {
  const std::string where = path() + ": line " + std::to_string(point_line_) + ", #20 CARTESIAN_POINT: ";
  const auto with_x = [&](const std::string& x) {
    return replaced(original_, point_, "#20 = CARTESIAN_POINT('',(" + x + ",0.423702927757,5.43633));");
  };
  EXPECT_EQ(refusal(with_x("inf")), where + "'inf' is not a finite number");
  EXPECT_EQ(refusal(with_x("-NaN")), where + "'-NaN' is not a finite number");
  EXPECT_EQ(refusal(with_x("-2.5E400")), where + "the number '-2.5E400' does not fit a double");
  EXPECT_EQ(refusal(with_x("123456789012345678901234567890")),
            where + "the integer '123456789012345678901234567890' does not fit OCCT's 32-bit integers");
}

TEST_F(StepPrecheck, HugeListIsRefused) {
  std::string items = "0.";
  items.reserve(3000000);
  for (int k = 1; k < 1000000; ++k) items += ",0.";
  EXPECT_EQ(refusal(replaced(original_, point_, "#20 = CARTESIAN_POINT('',(" + items + "));")),
            path() + ": line " + std::to_string(point_line_) +
                ", #20 CARTESIAN_POINT: a list of 100001 items or more (the limit is 100000)");
}

TEST_F(StepPrecheck, DanglingReferenceIsRefused) {
  const std::string vertex = "#19 = VERTEX_POINT('',#20);";
  EXPECT_EQ(refusal(replaced(original_, vertex, "#19 = VERTEX_POINT('',#999999);")),
            path() + ": line " + std::to_string(line_of(original_, vertex)) +
                ", #19 VERTEX_POINT: refers to #999999, which the file lacks");
}

TEST_F(StepPrecheck, UnterminatedStringIsRefusedAtItsStart) {
  // A string opened in the last entity runs to the end of the file (which still ends in END-ISO-10303-21;).
  const size_t data_end = original_.rfind("ENDSEC;");
  const std::string damaged =
      original_.substr(0, data_end) + "#99999 = DRAUGHTING_PRE_DEFINED_COLOUR('red);\n" + original_.substr(data_end);
  EXPECT_EQ(refusal(damaged), path() + ": line " + std::to_string(line_of(damaged, "#99999 =")) +
                                  ", #99999 DRAUGHTING_PRE_DEFINED_COLOUR: a string that is never closed");
}

TEST_F(StepPrecheck, SyntaxThePrecheckSkipsCorrectly) {
  // Quotes doubled inside strings, comments, binary literals, enumerations, typed parameters and complex
  // instances hold nothing the pass should refuse.
  const std::string bytes =
      "ISO-10303-21;\nHEADER;\nFILE_NAME('it''s (a) #1 ;','',(''),(''),'','','');\nENDSEC;\nDATA;\n"
      "/* #7 ( ' */ #1 = A('x',\"0F\",.T.,$,*,LENGTH_MEASURE(1.E+01),(#2,(1,-2,(3.5E-3))));\n"
      "#2 = (B(1) C('y',#1));\nENDSEC;\nEND-ISO-10303-21;\n";
  const StepPrecheckFigures figures = precheck_step(bytes, "inline.step");
  EXPECT_EQ(figures.entities, 2u);
  EXPECT_EQ(figures.references, 2u);
  EXPECT_EQ(figures.deepest, 4);
  EXPECT_EQ(figures.longest_list, 7u);
}

TEST(StepPrecheckCorpus, EveryCorpusFilePasses) {
  const std::vector<std::string> files = corpus_paths({"step/"});
  ASSERT_GE(files.size(), 15u);
  for (const std::string& relative : files) {
    const StepPrecheckFigures figures = precheck_step_file(corpus_file(relative));
    EXPECT_GT(figures.entities, 0u) << relative;
    EXPECT_LE(figures.deepest, 4) << relative;  // the limit (64) is 16 times that
  }
}

// IGES: Cube_10x10.igs (141 lines: S 1, G 3, D 72, P 64, T 1).
class IgesPrecheck : public ::testing::Test {
 protected:
  std::string write(const std::string& bytes) {
    const std::string path = folder_.file("damaged.igs");
    write_bytes(path, bytes);
    return path;
  }
  std::string refusal(const std::string& bytes) {
    const std::string path = write(bytes);
    const std::string message = error_of([&] { precheck_iges_file(path); });
    EXPECT_EQ(error_of([&] { read_iges(path); }), message);
    return message;
  }
  std::string path() const { return folder_.file("damaged.igs"); }

  const std::string original_ = read_file(corpus_file("iges/Cube_10x10.igs"));
  TemporaryFolder folder_;
};

TEST_F(IgesPrecheck, WrongTerminateCountIsRefused) {
  const std::string damaged = replaced(original_, "D     72P     64", "D     72P     65");
  const std::string file = write(damaged);
  EXPECT_EQ(error_of([&] { precheck_iges_file(file); }),
            file + ": line 141 (Terminate section): it counts 65 Parameter Data lines, the file has 64");
  // read_iges's framing check, which runs first, says it its own way.
  EXPECT_EQ(error_of([&] { read_iges(file); }),
            file + ": IGES file is damaged: its Terminate section counts 65 Parameter Data lines, the file has 64");
}

TEST_F(IgesPrecheck, DirectoryPointerPastTheParameterSectionIsRefused) {
  const std::string entry = "     186       1                                                00000000D      1";
  EXPECT_EQ(refusal(replaced(original_, entry, "     186     999" + entry.substr(16))),
            path() + ": line 5 (directory entry 1): its parameter data pointer 999 is outside the Parameter Data "
                     "section (lines 1 to 64)");
}

TEST_F(IgesPrecheck, NumberTooLargeForADoubleIsRefused) {
  // The last record, "314,0.,0.,0.,;" (directory entry 71): its first colour component made 1.0D400, the
  // data columns kept 64 wide.
  const std::string record = "314,0.,0.,0.,;                                                        71P     64";
  EXPECT_EQ(refusal(replaced(original_, record, "314,1.0D400,0.,0.,;                                                   71P     64")),
            path() + ": line 140 (directory entry 71, parameter 1): the number '1.0D400' does not fit a double");
}

TEST_F(IgesPrecheck, BsplineSurfaceDeclaringMoreThanItsRecordIsRefused) {
  // Directory entry 55, a 128 of 2 x 2 control points, made to declare K1 = 999 (1,000 x 2 points).
  const std::string data = "128,1,1,1,1,0,0,1,0,0,-0.001,-0.001,1.001,1.001,-0.001,-0.001,";
  const std::string tail = "55P     43";
  const auto line = [&](const std::string& text) { return text + std::string(70 - text.size(), ' ') + tail; };
  EXPECT_EQ(refusal(replaced(original_, line(data), line(replaced(data, "128,1,", "128,999,")))),
            path() + ": line 119 (directory entry 55): entity 128 declares K1 = 999, K2 = 1, M1 = 1, M2 = 1, which "
                     "needs more than 37 parameters; its record has 37");
}

TEST(IgesPrecheckCorpus, EveryCorpusFilePasses) {
  const std::vector<std::string> files = corpus_paths({"iges/"});
  ASSERT_GE(files.size(), 12u);
  for (const std::string& relative : files) {
    const IgesPrecheckFigures figures = precheck_iges_file(corpus_file(relative));
    EXPECT_GT(figures.directory_entries, 0u) << relative;
  }
}

}  // namespace
}  // namespace cadnurbs::test
