// cadnurbs batch (issue 14): the library listing (stable order, parts told by content, links out of the
// library refused), the shards, the output paths that may not escape OUT_DIR, and the command itself on
// small folders of real and broken files: every input once in the report, resuming, a killed run, a part
// that hangs.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "command_fixture.hpp"
#include "converters/batch/library_listing.hpp"
#include "converters/batch/worker_pool.hpp"

namespace cadnurbs::test {
namespace {

namespace fs = std::filesystem;

const std::string kStep = CADNURBS_SOURCE_DIR "/samples/capping-post.step";
const std::string kIges = CADNURBS_SOURCE_DIR "/samples/capping-post.iges";

class Batch : public CommandTest {
 protected:
  std::string make(const std::string& relative, const std::string& text) const {
    const fs::path p = fs::path(path(relative));
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }
  std::string copy(const std::string& from, const std::string& relative) const { return make(relative, read_file(from)); }
  nlohmann::json report(const std::string& out) const { return nlohmann::json::parse(read_file(out + "/report.json")); }
};

std::vector<std::string> names(const std::vector<LibraryPart>& parts) {
  std::vector<std::string> out;
  for (const auto& p : parts) out.push_back(p.relative);
  return out;
}

TEST_F(Batch, ListingIsStableTellsUnnamedPartsByContentAndRefusesLinksOut) {
  copy(kStep, "lib/b.step");
  copy(kIges, "lib/a/c.iges");
  copy(kStep, "lib/noext");
  make("lib/README.txt", "not a part\n");
  make("lib/notes", "not a part either\n");
  fs::create_symlink("/etc/hostname", path("lib/link.step"));
  const auto parts = list_library(path("lib"));
  EXPECT_EQ(names(parts), (std::vector<std::string>{"a/c.iges", "b.step", "link.step", "noext"}));
  ASSERT_EQ(parts.size(), 4u);
  EXPECT_FALSE(parts[1].by_content);
  EXPECT_TRUE(parts[3].by_content);
  ASSERT_NE(parts[3].format, nullptr);
  EXPECT_EQ(parts[3].format->extensions.front(), ".step");
  EXPECT_EQ(parts[2].refusal, "links to /etc/hostname, outside the library");
  EXPECT_EQ(parts[0].refusal, "");
}

TEST_F(Batch, InputsKeepOnlyTheNamedFormatsTheirOtherExtensionsAndRefusedLinksOfThem) {
  copy(kStep, "lib/b.step");
  copy(kStep, "lib/d.stp");
  copy(kIges, "lib/a/c.iges");
  copy(kStep, "lib/noext");
  make("lib/e.wrl", "#VRML V2.0 utf8\n");
  fs::create_symlink("/etc/hostname", path("lib/link.step"));
  const auto all = list_library(path("lib"));
  EXPECT_EQ(names(of_formats(all, {})), names(all));
  EXPECT_EQ(names(of_formats(all, {&named_input_format("step")})),
            (std::vector<std::string>{"b.step", "d.stp", "link.step", "noext"}));
  EXPECT_EQ(names(of_formats(all, {&named_input_format("IGES"), &named_input_format(".wrl")})),
            (std::vector<std::string>{"a/c.iges", "e.wrl"}));
}

TEST(BatchWorker, EveryWayAWorkerEndsHasItsOwnReason) {
  const ProcessLimits limits{300, 4096};
  WorkerOutcome outcome;
  outcome.status = W_EXITCODE(0, 0);
  EXPECT_EQ(outcome.reason(limits), "");
  outcome.status = W_EXITCODE(2, 0);
  EXPECT_EQ(outcome.reason(limits), "the worker ended with exit status 2");
  outcome = WorkerOutcome{};
  outcome.status = W_EXITCODE(0, SIGSEGV);
  EXPECT_EQ(outcome.reason(limits), "crashed with SIGSEGV");
  outcome.status = W_EXITCODE(0, SIGXCPU);
  EXPECT_EQ(outcome.reason(limits), "exceeded 300 s of CPU time");
  outcome.timed_out = true;
  outcome.status = W_EXITCODE(0, SIGKILL);
  EXPECT_EQ(outcome.reason(limits), "exceeded 300 s");
  outcome = WorkerOutcome{};
  outcome.not_started = "Resource temporarily unavailable";
  EXPECT_EQ(outcome.reason(limits), "no worker could be started (fork: Resource temporarily unavailable)");
}

TEST_F(Batch, ShardsAreDisjointAndCoverTheLibrary) {
  std::vector<LibraryPart> all(10);
  for (int i = 0; i < 10; ++i) all[i].relative = "p" + std::to_string(i);
  std::vector<std::string> seen;
  std::vector<size_t> sizes;
  for (int k = 0; k < 4; ++k) {
    const auto slice = shard_of(all, k, 4);
    sizes.push_back(slice.size());
    for (const auto& p : slice) seen.push_back(p.relative);
  }
  std::sort(seen.begin(), seen.end());
  EXPECT_EQ(seen, names(all));
  EXPECT_EQ(sizes, (std::vector<size_t>{3, 3, 2, 2}));
  EXPECT_THROW(shard_of(all, 4, 4), std::invalid_argument);
}

TEST_F(Batch, OutputsMayNotEscapeOutDir) {
  const std::string out = path("out");
  fs::create_directories(out);
  EXPECT_EQ(output_stem(out, "a/b.step"), fs::weakly_canonical(fs::path(out) / "a/b.step"));
  auto refusal = [&](const std::string& relative) {
    try {
      output_stem(out, relative);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(refusal("../x.step"), "its name climbs out of the folder ('..')");
  EXPECT_EQ(refusal("a/../../x.step"), "its name climbs out of the folder ('..')");
  EXPECT_EQ(refusal("/etc/x.step"), "its name is an absolute path");
  fs::create_directory_symlink(fs::temp_directory_path(), path("out/evil"));
  EXPECT_EQ(refusal("evil/x.step").rfind("its output would land outside OUT_DIR, at ", 0), 0u) << refusal("evil/x.step");
}

TEST_F(Batch, GoodPartsConvertBrokenOnesFailWithAReasonAndASecondRunRedoesOnlyALimitFailure) {
  copy(kStep, "lib/good.step");
  copy(kIges, "lib/sub/good.iges");
  make("lib/empty.step", "");
  make("lib/garbage.iges", std::string("\x00\x01\x02 not IGES at all\n", 22));
  make("lib/truncated.step", read_file(kStep).substr(0, 5000));
  copy(kStep, "lib/wrong.stl");  // a STEP file named as STL fails as STL
  // An assembly that contains itself (one usage occurrence of the corpus assembly made to relate #39 to
  // #39): OpenCASCADE's transfer recurses until the stack runs out.
  std::string assembly = read_file(CADNURBS_SHARED_DIR "/corpus/step/as1-oc-214.stp");
  const std::string usage = "NEXT_ASSEMBLY_USAGE_OCCURRENCE('1','nut_1','',#39,#742,$)";
  ASSERT_NE(assembly.find(usage), std::string::npos);
  assembly.replace(assembly.find(usage), usage.size(), "NEXT_ASSEMBLY_USAGE_OCCURRENCE('1','nut_1','',#39,#39,$)");
  make("lib/contains-itself.stp", assembly);
  // A real part whose read alone takes OpenCASCADE over 10 s here: beyond a 3 s limit, like a loop.
  copy(CADNURBS_SHARED_DIR "/corpus/step/11752.stp", "lib/slow.stp");
  const std::string out = path("out");
  const CommandResult r = run("batch " + path("lib") + " -o " + out + " --jobs 2 --timeout 3");
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_EQ(r.out, out + ": 8 parts: 8 converted now, 0 done before, 6 failed\n");
  const nlohmann::json j = report(out);
  ASSERT_EQ(j["parts"].size(), 8u);
  std::vector<std::string> inputs;
  for (const auto& part : j["parts"]) inputs.push_back(part["input"]);
  EXPECT_EQ(inputs, (std::vector<std::string>{"contains-itself.stp", "empty.step", "garbage.iges", "good.step",
                                              "slow.stp", "sub/good.iges", "truncated.step", "wrong.stl"}));
  EXPECT_EQ(j["parts"][0]["error"], "crashed with SIGSEGV while transferring");
  EXPECT_EQ(j["parts"][4]["error"].get<std::string>().rfind("exceeded ", 0), 0u) << j["parts"][4]["error"];
  for (const auto& part : j["parts"]) {
    const std::string input = part["input"];
    const bool good = input == "good.step" || input == "sub/good.iges";
    EXPECT_EQ(part["status"], good ? "ok" : "failed") << input;
    if (!good) {
      EXPECT_FALSE(part["error"].get<std::string>().empty()) << input;
    }
    EXPECT_EQ(fs::exists(out + "/" + input + ".x3dv"), good) << input;
    EXPECT_TRUE(fs::exists(out + "/" + input + ".json")) << input;
  }
  // The part redone below ends by a limit, whichever the load lets come first: the wall-time or CPU-time
  // limit (3 s), or the read's wall (2.7 s, then naming the face it was converting, which depends on
  // the load too): its line is the one line of the report a rerun may change.
  auto without_slow = [](std::string report) {
    const size_t at = report.find("- slow.stp: exceeded ");
    if (at != std::string::npos) report.erase(at, report.find('\n', at) - at);
    return report;
  };
  const std::string first_report = without_slow(read_file(out + "/report.md"));
  const CommandResult again = run("batch " + path("lib") + " -o " + out + " --jobs 2 --timeout 3");
  EXPECT_EQ(again.status, 3);
  // The part that exceeded the time limit is done again (a limit depends on the machine's load); the
  // others, failed for their content or converted, keep their records.
  EXPECT_EQ(again.out, out + ": 8 parts: 1 converted now, 7 done before, 6 failed\n");
  EXPECT_EQ(without_slow(read_file(out + "/report.md")), first_report);
  // A changed input is done again; the others are not.
  make("lib/empty.step", read_file(kStep));
  const CommandResult changed = run("batch " + path("lib") + " -o " + out + " --jobs 2 --timeout 3");
  EXPECT_EQ(changed.out, out + ": 8 parts: 2 converted now, 6 done before, 5 failed\n");
}

TEST_F(Batch, ARecordHoldsWhatTheConversionKnewAndMeasureAddsTheComparison) {
  copy(kStep, "lib/part.step");
  // What convert writes for the same part: batch's outputs must be these bytes.
  ASSERT_EQ(run("convert " + path("lib/part.step") + " -o " + path("convert.x3dv")).status, 0);
  ASSERT_EQ(run("convert " + path("lib/part.step") + " -o " + path("convert.stl")).status, 0);
  const std::string light = path("light");
  const CommandResult r = run("batch " + path("lib") + " -o " + light + " --jobs 1 --to x3dv,stl");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read_file(light + "/part.step.x3dv"), read_file(path("convert.x3dv")));
  EXPECT_EQ(read_file(light + "/part.step.stl"), read_file(path("convert.stl")));
  const nlohmann::json record = nlohmann::json::parse(read_file(light + "/part.step.json"));
  ASSERT_EQ(record["status"], "ok");
  const double d = record["deviation"];  // convert's default: 1e-3 of the diagonal
  EXPECT_NEAR(d, 1e-3 * record["diagonal"].get<double>(), 1e-12 * d);
  ASSERT_EQ(record["representations"].size(), 2u);
  const auto& nurbs = record["representations"][0];
  const auto& mesh = record["representations"][1];
  EXPECT_EQ(nurbs["key"], "x3dv");
  EXPECT_EQ(nurbs["kind"], "nurbs");
  EXPECT_EQ(nurbs["bytes"], fs::file_size(light + "/part.step.x3dv"));
  EXPECT_GT(nurbs["gzip_bytes"], 0);
  EXPECT_LT(nurbs["gzip_bytes"], nurbs["bytes"]);
  EXPECT_EQ(nurbs["deviation_basis"], "bound: nothing moved by more than the written precision");
  EXPECT_NEAR(nurbs["deviation"].get<double>(), 1e-6 * record["diagonal"].get<double>(), 1e-9 * d);
  EXPECT_EQ(mesh["key"], "stl");
  EXPECT_EQ(mesh["kind"], "mesh");
  EXPECT_EQ(mesh["bytes"], fs::file_size(light + "/part.step.stl"));
  EXPECT_EQ(mesh["deviation_basis"], "bound: the tessellator's certificate");
  EXPECT_GT(mesh["deviation"].get<double>(), 0.1 * d);
  EXPECT_LE(mesh["deviation"].get<double>(), d);
  EXPECT_EQ(record["mesh"]["certified_deviation"], mesh["deviation"]);
  // binary STL: 84 bytes and 50 a triangle
  EXPECT_EQ(mesh["bytes"].get<long>(), 84 + 50 * record["mesh"]["triangles"].get<long>());

  // --measure: the report's comparison, every figure saying how its deviation is known; the outputs
  // are still convert's.
  const std::string measured = path("measured");
  ASSERT_EQ(run("batch " + path("lib") + " -o " + measured + " --jobs 1 --measure --deviation 0.5").status, 0);
  EXPECT_EQ(read_file(measured + "/part.step.x3dv"), read_file(path("convert.x3dv")));
  const nlohmann::json full = nlohmann::json::parse(read_file(measured + "/part.step.json"));
  EXPECT_EQ(full["deviation"], 0.5);
  std::vector<std::string> keys;
  for (const auto& f : full["representations"]) {
    keys.push_back(f["key"]);
    EXPECT_FALSE(f["deviation_basis"].get<std::string>().empty()) << f["key"];
  }
  for (const char* key : {"x3dv-compact", "cnb", "wrl-mesh", "stl-mesh", "draco", "meshopt"})
    EXPECT_NE(std::find(keys.begin(), keys.end(), key), keys.end()) << key;
  // A record made without --measure is not reused by a run with it, nor the other way round.
  const CommandResult again = run("batch " + path("lib") + " -o " + light + " --jobs 1 --to x3dv,stl --measure");
  EXPECT_EQ(again.out, light + ": 1 parts: 1 converted now, 0 done before, 0 failed\n");
}

TEST_F(Batch, AKilledBatchLosesNothingAndTheRerunDoesOnlyWhatIsLeft) {
  for (const char* name : {"p1.step", "p2.step", "p3.step", "p4.step"}) copy(kStep, std::string("lib/") + name);
  const std::string whole = path("whole"), killed = path("killed");
  ASSERT_EQ(run("batch " + path("lib") + " -o " + whole + " --jobs 1").status, 0);
  // SIGKILL once the first part's record is on disk; the workers die with the batch.
  const std::string script = CADNURBS_EXE " batch " + path("lib") + " -o " + killed + " --jobs 1 2>/dev/null & pid=$!; " +
                             "while [ ! -e " + killed + "/p1.step.json ]; do sleep 0.02; done; kill -9 $pid; wait $pid";
  std::system(("bash -c '" + script + "'").c_str());
  const CommandResult rerun = run("batch " + path("lib") + " -o " + killed + " --jobs 1");
  EXPECT_EQ(rerun.status, 0) << rerun.err;
  int now = -1, before = -1;
  ASSERT_EQ(std::sscanf(rerun.out.c_str() + killed.size(), ": 4 parts: %d converted now, %d done before", &now, &before), 2)
      << rerun.out;
  EXPECT_GE(before, 1);
  EXPECT_LE(before, 3);  // the kill came before the last part was done
  EXPECT_EQ(now + before, 4);
  EXPECT_EQ(read_file(killed + "/report.md"), read_file(whole + "/report.md"));
}

TEST_F(Batch, APartThatHangsIsStoppedNamedAndTheBatchGoesOn) {
  copy(kStep, "lib/hangs.step");
  const std::string out = path("out");
  // the hang: faulty_reader_cadnurbs's reading child sleeps for ever once parsing starts (OpenCASCADE's
  // reader, walled in a child; our own reads the capping in-process)
  const CommandResult r = run_program(FAULTY_READER_CADNURBS,
                                      "batch " + path("lib") + " -o " + out + " --timeout 4 --reader occt",
                                      "CADNURBS_TEST_FAULT=parse:sleep ");
  EXPECT_EQ(r.status, 3);
  const nlohmann::json j = report(out);
  ASSERT_EQ(j["parts"].size(), 1u);
  EXPECT_EQ(j["parts"][0]["error"], "exceeded 3.6 s while parsing");
}

}  // namespace
}  // namespace cadnurbs::test
