// `cadnurbs batch --site` (issue 40): the site of a small library folder: a page, a .cnb and a picture per
// converted part, a row with its reason for a failed one, the shared files once; the sizes the command
// prints are the site's files as written and the library's meshes beside the parts; a second run
// rewrites nothing.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>

#include "command_fixture.hpp"

namespace cadnurbs::test {
namespace {

namespace fs = std::filesystem;

class BatchSite : public CommandTest {
 protected:
  void copy(const std::string& from, const std::string& relative) const {
    const fs::path to = path(relative);
    fs::create_directories(to.parent_path());
    fs::copy_file(from, to, fs::copy_options::overwrite_existing);
  }
};

long folder_bytes(const fs::path& folder) {
  long bytes = 0;
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    if (entry.is_regular_file()) bytes += static_cast<long>(entry.file_size());
  return bytes;
}

std::map<std::string, fs::file_time_type> file_times(const fs::path& folder) {
  std::map<std::string, fs::file_time_type> times;
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    if (entry.is_regular_file()) times[entry.path().string()] = entry.last_write_time();
  return times;
}

// Width and height from a PNG's IHDR chunk (bytes 16 to 23), after checking its signature.
std::pair<int, int> png_size(const std::string& png) {
  if (png.size() < 24 || png.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0) return {0, 0};
  auto number = [&](size_t at) {
    return int(uint8_t(png[at])) << 24 | int(uint8_t(png[at + 1])) << 16 | int(uint8_t(png[at + 2])) << 8 | int(uint8_t(png[at + 3]));
  };
  return {number(16), number(20)};
}

TEST_F(BatchSite, PagesPicturesAndAnIndexWhoseSizesAreTheFilesWritten) {
  const std::string samples = CADNURBS_SOURCE_DIR "/samples/";
  copy(samples + "capping-90.step", "lib/cappings/capping-90.step");
  copy(samples + "capping-90.stl", "lib/cappings/capping-90.stl");  // the mesh the library ships beside it
  copy(samples + "capping-end.step", "lib/cappings/capping-end.step");
  copy(samples + "capping-end.stl", "lib/cappings/capping-end.stl");
  copy(CADNURBS_SHARED_DIR "/corpus/step/screw.step", "lib/other/screw.step");
  {
    std::ofstream broken(path("lib/other/broken.step"));
    broken << read_file(samples + "capping-post.step").substr(0, 3000);
  }
  const std::string command = "batch " + path("lib") + " -o " + path("out") + " --inputs step --jobs 2 --site " + path("site");
  const CommandResult r = run(command);
  EXPECT_EQ(r.status, 3) << r.err;  // broken.step failed
  const std::regex site_line(R"((\S+): (\d+) part pages \((\d+) without a picture\), (\d+) bytes \((\d+) gzip'd\): shared (\d+), pages (\d+), \.cnb (\d+), pictures (\d+), index (\d+)\n)");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, site_line)) << r.out;
  EXPECT_EQ(m[1], path("site"));
  EXPECT_EQ(m[2], "3");
  EXPECT_EQ(m[3], "0");
  // The total is what the site's files weigh, and its parts add up to it.
  EXPECT_EQ(std::stol(m[4]), folder_bytes(path("site")));
  EXPECT_EQ(std::stol(m[6]), folder_bytes(path("site/cadnurbs-assets")));
  EXPECT_EQ(std::stol(m[6]) + std::stol(m[7]) + std::stol(m[8]) + std::stol(m[9]) + std::stol(m[10]), std::stol(m[4]));
  EXPECT_EQ(std::stol(m[10]), static_cast<long>(fs::file_size(path("site/index.html"))));
  EXPECT_LT(std::stol(m[5]), std::stol(m[4]));
  // The library's meshes: the two STL files beside the cappings (screw.step has none).
  const long meshes = static_cast<long>(fs::file_size(samples + "capping-90.stl") + fs::file_size(samples + "capping-end.stl"));
  EXPECT_NE(r.out.find("the library's meshes of 2 of these parts: " + std::to_string(meshes) + " bytes ("), std::string::npos) << r.out;

  const std::string index = read_file(path("site/index.html"));
  for (const std::string part : {"cappings/capping-90.step", "cappings/capping-end.step", "other/screw.step"}) {
    SCOPED_TRACE(part);
    // The page names the .cnb and the picture beside it and its script among the shared files one folder
    // up; the .cnb is the batch's.
    const std::string page = read_file(path("site/" + part + ".html"));
    const std::string cnb_name = fs::path(part).filename().string() + ".cnb";
    EXPECT_NE(page.find("data-part=\"" + cnb_name + "\""), std::string::npos);
    EXPECT_NE(page.find("src=\"" + fs::path(part).filename().string() + ".png\""), std::string::npos);
    EXPECT_NE(page.find("<script src=\"../cadnurbs-assets/site_start.js\" data-name=\""), std::string::npos);
    EXPECT_EQ(read_file(path("site/" + part + ".cnb")), read_file(path("out/" + part + ".cnb")));
    EXPECT_EQ(png_size(read_file(path("site/" + part + ".png"))), std::make_pair(160, 120));
    EXPECT_NE(index.find("<a href=\"" + part + ".html\">" + part + "</a>"), std::string::npos);
    EXPECT_NE(index.find("src=\"" + part + ".png\""), std::string::npos);
  }
  EXPECT_FALSE(fs::exists(path("site/other/broken.step.html")));
  EXPECT_NE(index.find("other/broken.step<br><span class=failed>"), std::string::npos);
  for (const char* shared : {"site_start.js", "viewer.js", "render_worker.js", "mesh_worker.js", "cadnurbs_wasm.wasm", "LICENSES.txt"})
    EXPECT_TRUE(fs::is_regular_file(path(std::string("site/cadnurbs-assets/") + shared))) << shared;
  EXPECT_EQ(read_file(path("site/cadnurbs-assets/cadnurbs_wasm.wasm")).substr(0, 4), std::string("\0asm", 4));

  // Again: nothing converted, nothing of the site rewritten.
  const auto before = file_times(path("site"));
  const CommandResult again = run(command);
  EXPECT_NE(again.out.find(": 4 parts: 0 converted now, 4 done before, 1 failed\n"), std::string::npos) << again.out;
  EXPECT_EQ(file_times(path("site")), before);
}

TEST_F(BatchSite, IsRefusedWithMergeAndShards) {
  const CommandResult merge = run("batch --merge " + path("out") + " --site " + path("site"));
  EXPECT_EQ(merge.status, 2);
  EXPECT_NE(merge.err.find("--site needs the library: run batch IN_DIR -o OUT_DIR --site DIR (done parts are reused)"), std::string::npos)
      << merge.err;
  const CommandResult shard = run("batch " + path("lib") + " -o " + path("out") + " --shard 0/2 --site " + path("site"));
  EXPECT_EQ(shard.status, 2);
  EXPECT_NE(shard.err.find("--site needs the whole library, not a --shard"), std::string::npos) << shard.err;
}

}  // namespace
}  // namespace cadnurbs::test
