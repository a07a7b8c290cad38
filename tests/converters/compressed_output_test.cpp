// `convert` to the formats that quantise positions (.drc, .glb): the decoded mesh stays within the
// deviation asked for, measured against the exact surfaces after reading the file back.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "analysis/measure/measure_deviation.hpp"
#include "analysis/measure/scene_area.hpp"
#include "converters/file_formats.hpp"
#include "formats/common/file_io.hpp"
#include "formats/draco/draco_mesh_codec.hpp"
#include "command_fixture.hpp"

namespace fs = std::filesystem;
using namespace cadnurbs;

namespace {

class CompressedOutput : public test::CommandTest {
 protected:
  // `cadnurbs convert IN -o OUT OPTIONS`; its exit status (stderr in stderr.txt).
  int convert(const std::string& in, const std::string& out, const std::string& options) {
    return run("convert " + in + " -o " + path(out) + " " + options).status;
  }
};

const std::string kCapping = std::string(CADNURBS_SOURCE_DIR) + "/samples/capping-90.step";

}  // namespace

TEST_F(CompressedOutput, ADracoFileDecodesWithinTheDeviation) {
  ASSERT_EQ(convert(kCapping, "c.drc", "--deviation 0.1"), 0) << read_file(path("stderr.txt"));
  const TriangleMesh decoded = decode_draco_mesh(read_file(path("c.drc")), "c.drc");
  const DeviationMeasure d = measure_deviation(decoded, read_scene(kCapping));
  EXPECT_LE(d.overall.max, 0.1);
  EXPECT_GT(d.overall.max, 0.05) << "the budget is used: the mesh is made at 0.07 and quantised within 0.03";
}

TEST_F(CompressedOutput, GlbFilesAreglTFAndCompressionMakesThemSmaller) {
  std::map<std::string, std::uintmax_t> size;
  for (const char* compress : {"none", "draco", "meshopt"}) {
    const std::string out = std::string("c-") + compress + ".glb";
    ASSERT_EQ(convert(kCapping, out, std::string("--deviation 0.1 --compress ") + compress), 0)
        << read_file(path("stderr.txt"));
    EXPECT_EQ(read_file(path(out)).substr(0, 4), "glTF");
    size[compress] = fs::file_size(path(out));
  }
  EXPECT_LT(size["draco"] * 10, size["none"]);
  EXPECT_LT(size["meshopt"] * 2, size["none"]);
}

TEST_F(CompressedOutput, CompressIsRefusedForOtherFormatsAndUnknownMethods) {
  EXPECT_EQ(convert(kCapping, "c.stl", "--compress draco"), 2);
  EXPECT_NE(read_file(path("stderr.txt")).find("--compress applies to .glb output only"), std::string::npos);
  EXPECT_EQ(convert(kCapping, "c.glb", "--compress zip"), 1);
  EXPECT_NE(read_file(path("stderr.txt")).find("c.glb: unknown --compress 'zip' (none, draco, meshopt)"), std::string::npos)
      << read_file(path("stderr.txt"));
  EXPECT_FALSE(fs::exists(path("c.glb")));
}

TEST_F(CompressedOutput, ConvertWritesAndReadsCompactBinaryNurbs) {
  const std::string in = std::string(CADNURBS_SOURCE_DIR) + "/samples/capping-90.x3dv";
  ASSERT_EQ(convert(in, "c.cnb", "--deviation 0.01"), 0) << read_file(path("stderr.txt"));
  EXPECT_LT(fs::file_size(path("c.cnb")), fs::file_size(in) / 4);
  ASSERT_EQ(convert(path("c.cnb"), "back.x3dv", ""), 0) << read_file(path("stderr.txt"));
  const Scene original = read_scene(in), back = read_scene(path("back.x3dv"));
  const SceneCounts a = count_entities(original), b = count_entities(back);
  EXPECT_EQ(a.surfaces, b.surfaces);
  EXPECT_EQ(a.control_points, b.control_points);
  EXPECT_NEAR(scene_area(back), scene_area(original), 1e-3 * scene_area(original));
}
