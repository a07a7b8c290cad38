// No face covered twice (issue 9): every face of 20 library parts meshed at D = 0.001 x diagonal has its
// mesh area within check_face_area's allowance of its trimmed NURBS area.
#include <gtest/gtest.h>

#include "analysis/measure/face_area_check.hpp"
#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "core/bounding_box.hpp"
#include "corpus_manifest.hpp"
#include "part_library.hpp"

namespace cadnurbs::test {
namespace {

class LibraryFaceAreas : public ::testing::TestWithParam<std::string> {};

TEST_P(LibraryFaceAreas, NoFaceBeyondItsAllowance) {
  const Scene exact = read_library_step(GetParam());
  const double d = 1e-3 * scene_bounding_box(exact).diagonal().norm();
  const Scene meshed = tessellate_to_deviation(exact, d);
  const auto checks = check_face_areas(exact, meshed, d);
  for (const auto& [face, check] : checks)
    EXPECT_FALSE(check.beyond()) << display_name(*face) << ": mesh " << check.mesh_area << ", face " << check.area
                                 << ", allowance " << check.allowance;
  const size_t faces = checks.size();
  EXPECT_GT(faces, 0u);
}

INSTANTIATE_TEST_SUITE_P(Library, LibraryFaceAreas, ::testing::ValuesIn(library_parts()),
                         [](const auto& info) { return corpus_test_name(info.param); });

}  // namespace
}  // namespace cadnurbs::test
