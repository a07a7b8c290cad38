// The committed capping samples, read back from every NURBS encoding, equal the generator's model
// within the precision the writer promises (1e-6 of the bounding-box diagonal).
#include <gtest/gtest.h>

#include "converters/file_formats.hpp"
#include "formats/common/file_io.hpp"
#include "core/bounding_box.hpp"
#include "samples/capping_shapes.hpp"

using namespace cadnurbs;

namespace {

void expect_near(const std::vector<double>& a, const std::vector<double>& b, double tol, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], tol) << what << " " << i;
}

class SampleRoundTrip : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {};

}  // namespace

TEST_P(SampleRoundTrip, ControlPointsWeightsAndKnotsSurvive) {
  const auto& [name, ext] = GetParam();
  const Scene model = capping_nurbs(bundled_capping(name));
  const Scene read = read_scene(std::string(CADNURBS_SOURCE_DIR) + "/samples/" + name + ext);
  const double tol = 1e-6 * scene_bounding_box(model).diagonal().norm();
  std::vector<const TrimmedSurface*> expected, actual;
  for_each_shape(model, [&](const Shape& s, const Eigen::Affine3d&, const Colour&) { expected.push_back(&std::get<TrimmedSurface>(s.geometry)); });
  for_each_shape(read, [&](const Shape& s, const Eigen::Affine3d&, const Colour&) { actual.push_back(&std::get<TrimmedSurface>(s.geometry)); });
  ASSERT_EQ(actual.size(), expected.size());
  for (size_t k = 0; k < expected.size(); ++k) {
    const NurbsSurface &e = expected[k]->surface, &a = actual[k]->surface;
    ASSERT_EQ(a.u_count, e.u_count);
    ASSERT_EQ(a.v_count, e.v_count);
    EXPECT_EQ(a.u_order, e.u_order);
    EXPECT_EQ(a.v_order, e.v_order);
    expect_near(a.u_knots, e.u_knots, 1e-9, "u knots");
    expect_near(a.v_knots, e.v_knots, 1e-9, "v knots");
    for (size_t i = 0; i < e.points.size(); ++i) EXPECT_LT((a.points[i] - e.points[i]).norm(), tol) << i;
    if (e.is_rational()) expect_near(a.weights, e.weights, 1e-6, "weights");
    ASSERT_EQ(actual[k]->loops.size(), expected[k]->loops.size());
    for (size_t l = 0; l < expected[k]->loops.size(); ++l) {
      const auto& ec = std::get<NurbsCurve>(expected[k]->loops[l].segments.at(0));
      const auto& ac = std::get<NurbsCurve>(actual[k]->loops[l].segments.at(0));
      expect_near(ac.knots, ec.knots, 1e-9, "trim knots");
      expect_near(ac.weights, ec.weights, 1e-6, "trim weights");
      for (size_t i = 0; i < ec.points.size(); ++i) EXPECT_LT((ac.points[i] - ec.points[i]).norm(), 1e-6) << i;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Samples, SampleRoundTrip,
                         ::testing::Combine(::testing::ValuesIn(capping_shape_names()),
                                            ::testing::Values(".wrl", ".x3dv", ".x3d")),
                         [](const auto& info) {
                           std::string n = std::get<0>(info.param) + std::get<1>(info.param);
                           for (auto& c : n) if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

TEST(SampleFiles, Vrml97GroupsTheCappingSurfacesInOneNurbsGroup) {
  const std::string text = read_file(std::string(CADNURBS_SOURCE_DIR) + "/samples/capping-90.wrl");
  size_t groups = 0;
  for (size_t at = text.find("NurbsGroup {"); at != std::string::npos; at = text.find("NurbsGroup {", at + 1)) ++groups;
  EXPECT_EQ(groups, 1u);
  EXPECT_NE(text.find("EXTERNPROTO NurbsGroup ["), std::string::npos);
  // Read back, the three surfaces belong to the capping node again.
  const Scene scene = read_scene(std::string(CADNURBS_SOURCE_DIR) + "/samples/capping-90.wrl");
  EXPECT_EQ(scene.root.shapes.size(), 3u);
  EXPECT_TRUE(scene.root.children.empty());
}
