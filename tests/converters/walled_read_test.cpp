// converters/walled_read through the real command line: OCCT's crashes, hangs and allocations end the child
// process, not cadnurbs, and come back as one line naming the file, the stage and the reason; a file read
// through the wall converts to the same bytes as one read in-process. The faults are made by
// faulty_reader_cadnurbs (the same command line with a fault hook in its reading child).
#include <algorithm>
#include <fstream>

#include "converters/commands.hpp"
#include "command_fixture.hpp"

namespace cadnurbs::test {
namespace {

const std::string kCorpusStep = CADNURBS_SHARED_DIR "/corpus/step/io1-cm-214.stp";
// Our own STEP reader reads in the command's process, without a wall: the faults below are OCCT's.
const std::string kOcct = " --reader occt ";
const std::string kCorpusIges = CADNURBS_SHARED_DIR "/corpus/iges/Cube_10x10.igs";

class WalledRead : public CommandTest {
 protected:
  // cadnurbs ARGUMENTS with the fault STAGE:ACTION in its reading child (faulty_reader_cadnurbs.cpp).
  CommandResult run_with_fault(const std::string& arguments, const std::string& fault) {
    return run_program(FAULTY_READER_CADNURBS, arguments, "CADNURBS_TEST_FAULT='" + fault + "' ");
  }
};

TEST_F(WalledRead, DeeplyNestedPointIsOneLine) {
  // The crash: a CARTESIAN_POINT nested 100,000 parentheses deep overflowed OCCT's parser stack.
  // Here the STEP pre-check refuses it in the child before OCCT parses it: one line of the child's own,
  // naming the file, passed through (its wording is the pre-check's; this test asserts that it is one
  // line, names the file and is not a crash).
  const std::string path = this->path("deep.step");
  std::ofstream(path) << "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION((''),'2;1');\nFILE_NAME('deep','',(''),(''),'','','');\n"
                      << "FILE_SCHEMA(('AUTOMOTIVE_DESIGN'));\nENDSEC;\nDATA;\n#1=CARTESIAN_POINT(''," << std::string(100000, '(')
                      << "0.,0.,0." << std::string(100000, ')') << ");\nENDSEC;\nEND-ISO-10303-21;\n";
  const CommandResult r = run("info " + path);
  EXPECT_EQ(r.status, 1);
  const std::string prefix = "cadnurbs info: " + path + ": ";
  EXPECT_EQ(r.err.rfind(prefix, 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.err.find("crashed"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
}

TEST_F(WalledRead, CrashWhileParsingIsNamed) {
  const CommandResult r = run_with_fault("info " + kCorpusIges, "parse:segv");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "cadnurbs info: " + kCorpusIges + ": crashed with SIGSEGV while parsing\n");
  EXPECT_EQ(r.out, "");
}

TEST_F(WalledRead, CrashInAStageIsNamed) {
  const std::string out = path("out.x3dv");
  const CommandResult r = run_with_fault("convert " + kCorpusStep + kOcct + "-o " + out, "transfer:segv");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "cadnurbs convert: " + kCorpusStep + ": crashed with SIGSEGV while transferring\n");
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST_F(WalledRead, HangIsStoppedAtTheTimeLimit) {
  // The child sleeps for ever once parsing starts; on a loaded machine starting the child (loading this
  // executable and OCCT) can itself take a second, so the stage named is "starting" or "parsing".
  const CommandResult r = run_with_fault("info --time-limit 1 " + kCorpusIges, "parse:sleep");
  EXPECT_EQ(r.status, 1);
  const std::string head = "cadnurbs info: " + kCorpusIges + ": exceeded 1 s while ";
  EXPECT_TRUE(r.err == head + "parsing\n" || r.err == head + "starting\n") << r.err;
}

TEST_F(WalledRead, CpuLimitIsNamed) {
  // The kernel's SIGXCPU at RLIMIT_CPU (raised by the hook: a busy child reaches the wall-time limit
  // first, whose message the test above checks).
  const CommandResult r = run_with_fault("info --time-limit 2.5 " + kCorpusStep + kOcct, "transfer:xcpu");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "cadnurbs info: " + kCorpusStep + ": exceeded 2.5 s of CPU time while transferring\n");
  EXPECT_EQ(r.out, "");
}

TEST_F(WalledRead, AllocationIsStoppedAtTheMemoryLimit) {
  const CommandResult r = run_with_fault("info --memory-limit 256 " + kCorpusStep + kOcct, "face 2:alloc");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "cadnurbs info: " + kCorpusStep + ": exceeded the memory limit of 256 MB while converting face 2\n");
}

TEST_F(WalledRead, ChildRefusalPassesThroughUnchanged) {
  const std::string path = this->path("cut.step");
  const std::string text = read_file(kCorpusStep);
  std::ofstream(path) << text.substr(0, text.size() / 2);
  const CommandResult r = run("info " + path);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "cadnurbs info: " + path + ": STEP file is truncated (no END-ISO-10303-21; at its end)\n");
}

TEST_F(WalledRead, LimitsMustBePositive) {
  const CommandResult r = run("convert " + kCorpusStep + " -o " + path("x.wrl") + " --time-limit 0");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "cadnurbs convert: --time-limit needs a positive number of seconds, not '0'\n");
  const CommandResult m = run("report " + kCorpusStep + " --memory-limit 1.5");
  EXPECT_EQ(m.status, 2);
  EXPECT_EQ(m.err, "cadnurbs report: --memory-limit needs a whole number of megabytes from 1, not '1.5'\n");
}

TEST_F(WalledRead, WalledConversionWritesTheInProcessBytes) {
  // run_convert called here reads in-process (its context has no wall). cadnurbs convert runs one thread
  // when it reads, so its child is a plain fork; faulty_reader_cadnurbs with CADNURBS_TEST_EXEC=1 execs
  // itself, as a process with threads must.
  for (const std::string& input : {kCorpusStep, kCorpusIges}) {
    const std::string forked = path("forked.x3dv"), execed = path("execed.x3dv"), in_process = path("in_process.x3dv");
    const CommandResult r = run("convert " + input + " -o " + forked);
    ASSERT_EQ(r.status, 0) << r.err;
    const CommandResult e = run_program(FAULTY_READER_CADNURBS, "convert " + input + " -o " + execed, "CADNURBS_TEST_EXEC=1 ");
    ASSERT_EQ(e.status, 0) << e.err;
    ASSERT_EQ(run_convert({input, "-o", in_process}), 0);
    const std::string expected = read_file(in_process);
    EXPECT_GT(expected.size(), 500u);
    EXPECT_TRUE(read_file(forked) == expected) << input;
    EXPECT_TRUE(read_file(execed) == expected) << input;
  }
}

}  // namespace
}  // namespace cadnurbs::test
