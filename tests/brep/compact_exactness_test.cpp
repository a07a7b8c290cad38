// The compact writer against --exact-nurbs on every STEP/IGES file of the corpus (compact_exactness.hpp).
#include <gtest/gtest.h>

#include "compact_exactness.hpp"
#include "corpus_manifest.hpp"
#include "formats/iges/iges_reader.hpp"
#include "formats/step/step_reader.hpp"

namespace cadnurbs::test {
namespace {

class CorpusCompact : public ::testing::TestWithParam<std::string> {};

TEST_P(CorpusCompact, SameSurfacesAsExactNurbs) {
  const std::string& relative = GetParam();
  const std::string path = corpus_file(relative);
  const BrepTranslation t = relative.rfind("step/", 0) == 0 ? read_step(path) : read_iges(path);
  check_compact_is_exact(t.scene, relative);
}

INSTANTIATE_TEST_SUITE_P(Corpus, CorpusCompact, ::testing::ValuesIn(corpus_paths({"step/", "iges/"})),
                         [](const auto& info) { return corpus_test_name(info.param); });

}  // namespace
}  // namespace cadnurbs::test
