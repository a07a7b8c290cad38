// The compact writer against --exact-nurbs on every STEP/IGES file of the corpus (compact_exactness.hpp).
// Files whose faces carry hundreds of knots take minutes for the area to 1e-7: they are checked by the
// executable compact_exactness_long (this file with CADNURBS_LONG_CORPUS), which bench/compact_exactness.sh
// runs; ctest does not.
#include <gtest/gtest.h>

#include <algorithm>

#include "compact_exactness.hpp"
#include "corpus_manifest.hpp"
#include "formats/iges/iges_reader.hpp"
#include "formats/step/step_reader.hpp"

namespace cadnurbs::test {
namespace {

const std::vector<std::string> kLong = {"step/linkrods.step", "step/11752.stp", "step/Ventilator.stp",
                                        "iges/impeller.igs", "iges/wing.iges", "iges/goteborg.iges"};

std::vector<std::string> corpus_files(bool long_ones) {
  std::vector<std::string> out;
  for (const auto& path : corpus_paths({"step/", "iges/"}))
    if ((std::find(kLong.begin(), kLong.end(), path) != kLong.end()) == long_ones) out.push_back(path);
  return out;
}

void check(const std::string& relative) {
  const std::string path = corpus_file(relative);
  const BrepTranslation t = relative.rfind("step/", 0) == 0 ? read_step(path) : read_iges(path);
  check_compact_is_exact(t.scene, relative);
}

#ifdef CADNURBS_LONG_CORPUS
constexpr bool kLongOnes = true;
#else
constexpr bool kLongOnes = false;
#endif

class CorpusCompact : public ::testing::TestWithParam<std::string> {};
TEST_P(CorpusCompact, SameSurfacesAsExactNurbs) { check(GetParam()); }
INSTANTIATE_TEST_SUITE_P(Corpus, CorpusCompact, ::testing::ValuesIn(corpus_files(kLongOnes)),
                         [](const auto& info) { return corpus_test_name(info.param); });

}  // namespace
}  // namespace cadnurbs::test
