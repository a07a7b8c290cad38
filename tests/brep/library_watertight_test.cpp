// Our own NURBS files of 20 library parts mesh as watertight as the STEP files (read_back_watertight.hpp).
#include <gtest/gtest.h>

#include "corpus_manifest.hpp"
#include "part_library.hpp"
#include "read_back_watertight.hpp"

namespace cadnurbs::test {
namespace {

class LibraryWatertight : public ::testing::TestWithParam<std::string> {};

TEST_P(LibraryWatertight, ReadBackAsClosedAsTheStep) {
  check_read_back_watertight(read_library_step(GetParam()), library_part_name(GetParam()));
}

INSTANTIATE_TEST_SUITE_P(Library, LibraryWatertight, ::testing::ValuesIn(library_parts()),
                         [](const auto& info) { return corpus_test_name(info.param); });

}  // namespace
}  // namespace cadnurbs::test
