// Our own NURBS files mesh as watertight as the corpus B-reps they came from (read_back_watertight.hpp).
#include <gtest/gtest.h>

#include "corpus_manifest.hpp"
#include "formats/iges/iges_reader.hpp"
#include "formats/step/step_reader.hpp"
#include "read_back_watertight.hpp"

namespace cadnurbs::test {
namespace {

class ReadBackWatertight : public ::testing::TestWithParam<std::string> {};

TEST_P(ReadBackWatertight, AsClosedAsTheBrep) {
  const std::string& relative = GetParam();
  const std::string path = corpus_file(relative);
  const Scene source = relative.rfind("step/", 0) == 0 ? read_step(path).scene : read_iges(path).scene;
  check_read_back_watertight(source, relative);
}

// The corpus's closed solids that mesh in seconds (the others take minutes four times over).
INSTANTIATE_TEST_SUITE_P(Corpus, ReadBackWatertight,
                         ::testing::Values("step/screw.step", "step/io1-cm-214.stp", "step/as1_pe_203.stp",
                                           "iges/Cube_10x10.igs"),
                         [](const auto& info) { return corpus_test_name(info.param); });

}  // namespace
}  // namespace cadnurbs::test
