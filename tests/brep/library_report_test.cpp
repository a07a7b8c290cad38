// `cadnurbs report` over the 20 library parts and two broken files: it finishes, reports every part,
// lists the broken ones with their reasons, exits with the "some failed" status, and every mesh it
// measured lies within D after decoding.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "formats/common/file_io.hpp"
#include "part_library.hpp"

namespace fs = std::filesystem;

namespace cadnurbs::test {
namespace {

TEST(LibraryReport, TwentyPartsAndTwoBrokenFiles) {
  const fs::path dir = fs::temp_directory_path() / ("cadnurbs_library_report_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  // A STEP file cut off in its data section, and a file that is no STL at all.
  const std::string step = read_file(library_file(library_parts()[0], ".step"));
  write_file_atomically((dir / "truncated.step").string(), step.substr(0, step.size() / 3));
  write_file_atomically((dir / "not-a-mesh.stl").string(), "this is not an STL file\n");
  std::string inputs = (dir / "truncated.step").string() + " ";
  for (const auto& part : library_parts()) inputs += "'" + library_file(part, ".step") + "' ";
  inputs += (dir / "not-a-mesh.stl").string();

  const std::string command = std::string(CADNURBS_EXE) + " report " + inputs + " --format json -o " +
                              (dir / "r.json").string() + " 2>" + (dir / "err.txt").string();
  const int status = WEXITSTATUS(std::system(command.c_str()));
  EXPECT_EQ(status, 3) << read_file((dir / "err.txt").string());
  const std::string err = read_file((dir / "err.txt").string());
  EXPECT_NE(err.find("2 of 22 inputs failed"), std::string::npos) << err;

  const auto report = nlohmann::json::parse(read_file((dir / "r.json").string()));
  ASSERT_EQ(report["parts"].size(), 22u);
  int failed = 0;
  for (const auto& part : report["parts"]) {
    const std::string input = part["input"];
    if (part["status"] == "failed") {
      ++failed;
      EXPECT_TRUE(input.find("truncated.step") != std::string::npos || input.find("not-a-mesh.stl") != std::string::npos)
          << input << ": " << part["error"];
      EXPECT_FALSE(part["error"].get<std::string>().empty());
      continue;
    }
    const double d = part["deviation"];
    for (const auto& r : part["representations"])
      if (r["kind"] == "mesh" && !r["deviation"].is_null()) EXPECT_LE(r["deviation"].get<double>(), d) << input << " " << r["key"];
    bool has_cnb = false;
    for (const auto& r : part["representations"]) has_cnb |= r["key"] == "cnb";
    EXPECT_TRUE(has_cnb) << input;
  }
  EXPECT_EQ(failed, 2);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cadnurbs::test
