// Our own STEP reader (formats/step/native) against OpenCASCADE's reading of the same file, on every STEP
// file of the shared corpus: either the native reader refuses it, with the reason this table expects, or
// its scene passes expect_same_as_occt (native_comparison.hpp).
#include <gtest/gtest.h>

#include <cstdio>
#include <map>

#include "corpus_manifest.hpp"
#include "formats/step/native/read_step_native.hpp"
#include "native_comparison.hpp"

namespace cadnurbs::test {
namespace {

// Corpus files the native reader hands to OpenCASCADE, and the start of the reason it gives.
const std::map<std::string, std::string>& expected_refusals() {
  static const std::map<std::string, std::string> table = {};
  return table;
}

class NativeStepCorpus : public ::testing::TestWithParam<std::string> {};

TEST_P(NativeStepCorpus, SameAsOpenCascade) {
  const std::string relative = GetParam();
  const std::string path = corpus_file(relative);
  const auto refusal = expected_refusals().find(relative);
  BrepTranslation native;
  try {
    native = read_step_native(path);
  } catch (const step::OutsideNativeSubset& outside) {
    ASSERT_NE(refusal, expected_refusals().end()) << "refused: " << outside.what();
    EXPECT_EQ(std::string(outside.what()).rfind(refusal->second, 0), 0u) << outside.what();
    std::printf("| %-28s | refused: %s |\n", relative.c_str(), outside.what());
    return;
  }
  ASSERT_EQ(refusal, expected_refusals().end()) << "read natively, though the table expects a refusal";
  expect_same_as_occt(native, path, relative);
}

INSTANTIATE_TEST_SUITE_P(Corpus, NativeStepCorpus, ::testing::ValuesIn(corpus_paths({"step/"})),
                         [](const auto& info) { return corpus_test_name(info.param); });

}  // namespace
}  // namespace cadnurbs::test
