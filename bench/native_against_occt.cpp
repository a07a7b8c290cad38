// Our own STEP reader against OpenCASCADE's on every part of the library (issue 37's check on all 1,358
// parts; ctest holds 20 of them and the corpus): tests/brep/native_comparison's expect_same_as_occt for
// each STEP file under the given folders (names, placements, surface types, colours, every face's area
// within 1e-6 relative, the certified mesh within D = 0.01 x the diagonal of OCCT's faces, watertight).
// One table row per part; a part the native reader hands to OCCT is skipped with its reason.
// Usage: native_against_occt FOLDER... [--gtest_filter=...]   (GTEST_TOTAL_SHARDS / GTEST_SHARD_INDEX to
// split the parts over processes)
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "formats/step/native/read_step_native.hpp"
#include "native_comparison.hpp"

namespace {

std::vector<std::string>& parts() {
  static std::vector<std::string> files;
  return files;
}

class NativeAgainstOcct : public ::testing::TestWithParam<std::string> {};

TEST_P(NativeAgainstOcct, SameAsOpenCascade) {
  const std::string path = GetParam();
  cadnurbs::BrepTranslation native;
  try {
    native = cadnurbs::read_step_native(path);
  } catch (const cadnurbs::step::OutsideNativeSubset& outside) {
    GTEST_SKIP() << "handed to OpenCASCADE: " << outside.what();
  }
  cadnurbs::test::expect_same_as_occt(native, path, std::filesystem::path(path).filename().string());
}

INSTANTIATE_TEST_SUITE_P(Library, NativeAgainstOcct, ::testing::ValuesIn(parts()), [](const auto& info) {
  std::string name = std::filesystem::path(info.param).stem().string();
  for (auto& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name + "_" + std::to_string(info.index);
});

}  // namespace

int main(int argc, char** argv) {
  // The parts are listed before InitGoogleTest, which instantiates the parameterised tests.
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]).rfind("--", 0) != 0)
      for (const auto& entry : std::filesystem::recursive_directory_iterator(argv[i])) {
      std::string ext = entry.path().extension().string();
      std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
      if (entry.is_regular_file() && (ext == ".step" || ext == ".stp")) parts().push_back(entry.path().string());
    }
  std::sort(parts().begin(), parts().end());
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
