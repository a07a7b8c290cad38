// The compact writer against --exact-nurbs on 20 parts of the real part library (compact_exactness.hpp).
#include <gtest/gtest.h>

#include <filesystem>

#include "compact_exactness.hpp"
#include "corpus_manifest.hpp"
#include "formats/step/step_reader.hpp"
#include "part_library.hpp"

namespace cadnurbs::test {
namespace {

class LibraryCompact : public ::testing::TestWithParam<std::string> {};

TEST_P(LibraryCompact, SameSurfacesAsExactNurbs) {
  const std::string path = library_file(GetParam(), ".step");
  ASSERT_TRUE(std::filesystem::exists(path)) << path << " (scripts/fetch-part-library.sh fetches it)";
  check_compact_is_exact(read_step(path).scene, library_part_name(GetParam()));
}

INSTANTIATE_TEST_SUITE_P(Library, LibraryCompact, ::testing::ValuesIn(library_parts()),
                         [](const auto& info) { return corpus_test_name(info.param); });

}  // namespace
}  // namespace cadnurbs::test
