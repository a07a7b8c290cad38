// The compact writer against --exact-nurbs on 20 parts of the real part library (compact_exactness.hpp).
#include <gtest/gtest.h>

#include "compact_exactness.hpp"
#include "corpus_manifest.hpp"
#include "part_library.hpp"

namespace cadnurbs::test {
namespace {

class LibraryCompact : public ::testing::TestWithParam<std::string> {};

TEST_P(LibraryCompact, SameSurfacesAsExactNurbs) {
  check_compact_is_exact(read_library_step(GetParam()), library_part_name(GetParam()));
}

INSTANTIATE_TEST_SUITE_P(Library, LibraryCompact, ::testing::ValuesIn(library_parts()),
                         [](const auto& info) { return corpus_test_name(info.param); });

}  // namespace
}  // namespace cadnurbs::test
