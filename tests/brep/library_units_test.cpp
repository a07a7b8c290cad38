// `cadnurbs convert PART.step --units kicad` puts a library part where KiCad's own mesh of it is: the
// written file (compact .x3dv and .wrl), read back and meshed, has the bounding box of the .wrl KiCad
// ships for the part within 1 % of the part's size, corner by corner. (Control nets overreach trimmed
// faces, so the box is taken on the mesh, not on the NURBS.)
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <unistd.h>

#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "core/bounding_box.hpp"
#include "corpus_manifest.hpp"
#include "formats/vrml/vrml_reader.hpp"
#include "part_library.hpp"

namespace fs = std::filesystem;

namespace cadnurbs::test {
namespace {

class LibraryKicadUnits : public ::testing::TestWithParam<std::string> {};

TEST_P(LibraryKicadUnits, OutputOverlaysTheShippedMesh) {
  const std::string step = library_file(GetParam(), ".step"), shipped = library_file(GetParam(), ".wrl");
  ASSERT_TRUE(fs::exists(step)) << step << " (scripts/fetch-part-library.sh fetches it)";
  const auto kicad = scene_bounding_box(read_vrml(shipped));
  const double size = kicad.diagonal().norm();
  ASSERT_GT(size, 0) << shipped;

  const fs::path dir = fs::temp_directory_path() / ("cadnurbs_units_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  for (const char* ext : {".x3dv", ".wrl"}) {
    const std::string out = (dir / ("part" + std::string(ext))).string();
    const std::string command = std::string(CADNURBS_EXE) + " convert '" + step + "' --units kicad -o " + out;
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    const auto ours = scene_bounding_box(tessellate_to_deviation(read_vrml(out), 1e-4 * size));
    EXPECT_LE((ours.min() - kicad.min()).cwiseAbs().maxCoeff(), 0.01 * size)
        << ext << " min " << ours.min().transpose() << " KiCad " << kicad.min().transpose();
    EXPECT_LE((ours.max() - kicad.max()).cwiseAbs().maxCoeff(), 0.01 * size)
        << ext << " max " << ours.max().transpose() << " KiCad " << kicad.max().transpose();
  }
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Library, LibraryKicadUnits, ::testing::ValuesIn(library_parts()),
                         [](const auto& info) { return corpus_test_name(info.param); });

}  // namespace
}  // namespace cadnurbs::test
