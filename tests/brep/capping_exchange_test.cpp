// The bundled cappings written as STEP and IGES and read back: same faces, same area, and (STEP) one
// closed valid solid.
#include <gtest/gtest.h>

#include <BRepCheck_Analyzer.hxx>
#include <ShapeAnalysis_FreeBounds.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Compound.hxx>
#include <cstdlib>

#include "formats/common/file_io.hpp"
#include "formats/iges/iges_reader.hpp"
#include "formats/iges/iges_writer.hpp"
#include "formats/step/step_reader.hpp"
#include "formats/step/step_writer.hpp"
#include "occt_reference.hpp"
#include "samples/capping_shapes.hpp"
#include "temporary_folder.hpp"
#include "trimmed_measure.hpp"

namespace cadnurbs::test {
namespace {

SurfaceMeasure scene_measure(const Scene& scene) {
  SurfaceMeasure total;
  for_each_shape(scene, [&](const Shape& shape, const Eigen::Affine3d& world, const Colour&) {
    if (const auto* t = std::get_if<TrimmedSurface>(&shape.geometry)) {
      const auto m = measure_trimmed_surface(*t, world);
      total.area += m.area;
      total.volume += m.volume;
    }
  });
  return total;
}

struct Format {
  const char* extension;
  void (*write)(const std::string&, const Scene&);
  BrepTranslation (*read)(const std::string&, const ReadStageListener&);
};

class CappingExchange : public ::testing::TestWithParam<std::tuple<std::string, int>> {
 protected:
  static constexpr std::array<Format, 2> formats = {{{".step", write_step, read_step}, {".igs", write_iges, read_iges}}};
};

TEST_P(CappingExchange, RoundTripKeepsFacesAreaNamesAndColours) {
  const auto& [name, format_index] = GetParam();
  const Format& format = formats[format_index];
  const Scene scene = capping_nurbs(bundled_capping(name));
  const SurfaceMeasure original = scene_measure(scene);
  TemporaryFolder folder;
  const std::string path = folder.file(name + format.extension);
  format.write(path, scene);
  ASSERT_TRUE(std::filesystem::exists(path));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(folder.path()), std::filesystem::directory_iterator()), 1)
      << "the temporary file is gone";

  const BrepTranslation back = format.read(path, {});
  EXPECT_EQ(back.face_count, 3);
  EXPECT_TRUE(back.fallbacks.empty());
  for (const auto& f : back.fallbacks) ADD_FAILURE() << "fallback face " << f.face_index << ": " << f.reason;
  const SurfaceMeasure read = scene_measure(back.scene);
  EXPECT_NEAR(read.area / original.area, 1.0, 1e-3) << "area written " << original.area << " read " << read.area;
  EXPECT_EQ(back.scene.source_unit.name, "mm");
  EXPECT_EQ(back.scene.root.name, name);
  const Colour oak = *scene.root.colour;
  bool coloured = true;
  for_each_shape(back.scene, [&](const Shape&, const Eigen::Affine3d&, const Colour& c) {
    coloured = coloured && std::abs(c.r - oak.r) < 2e-3 && std::abs(c.g - oak.g) < 2e-3 && std::abs(c.b - oak.b) < 2e-3;
  });
  EXPECT_TRUE(coloured) << "the capping's oak colour is lost";

  // OCCT's own view of the written file.
  const OcctReference reference = occt_reference(path);
  EXPECT_EQ(reference.faces, 3);
  // OCCT's default integration is 1 % off on the swept body; its adaptive one is not.
  EXPECT_NEAR(reference.adaptive_area / original.area, 1.0, 1e-3);
  std::printf("| %-12s | %-5s | area %.8g written, %.8g read back, OCCT %.8g | solids %d |\n", name.c_str(),
              format.extension, original.area, read.area, reference.adaptive_area, reference.solids);
  if (std::string(format.extension) == ".step") {
    // Sewing closes the body with its lids: one valid solid without free edges, outward.
    EXPECT_EQ(reference.solids, 1);
    EXPECT_TRUE(reference.faces_all_in_solids);
    EXPECT_TRUE(BRepCheck_Analyzer(reference.shape).IsValid());
    ShapeAnalysis_FreeBounds free_bounds(reference.shape);
    TopTools_IndexedMapOfShape free_edges;
    TopExp::MapShapes(free_bounds.GetOpenWires(), TopAbs_EDGE, free_edges);
    EXPECT_EQ(free_edges.Extent(), 0);
    EXPECT_NEAR(reference.adaptive_volume / original.volume, 1.0, 1e-3) << "volume of the solid vs the scene's";
    EXPECT_NEAR(read.volume / original.volume, 1.0, 1e-3);
    // Our own STEP reader read it (the area above is its reading): no note says OpenCASCADE did. The
    // moulded and post cappings' profile corners (knots of full multiplicity) had stopped it: Newton from
    // an edge sample on a corner stayed there, "an edge lies 26 mm (78.3 mm) off the surface".
    for (const auto& note : back.notes) ADD_FAILURE() << note;
  }
}

TEST(CappingExchangeOutput, IsReproducibleWithSourceDateEpoch) {
  // The samples under samples/ are regenerated and compared byte for byte.
  const Scene scene = capping_nurbs(bundled_capping("capping-90"));
  ::setenv("SOURCE_DATE_EPOCH", "1700000000", 1);
  for (const char* extension : {".step", ".igs"}) {
    TemporaryFolder first, second;
    const std::string a = first.file(std::string("capping-90") + extension), b = second.file(std::string("capping-90") + extension);
    const auto write = std::string(extension) == ".step" ? write_step : write_iges;
    write(a, scene);
    write(b, scene);
    EXPECT_EQ(read_file(a), read_file(b)) << extension;
    EXPECT_NE(read_file(a).find(std::string(extension) == ".step" ? "2023-11-14T22:13:20" : "20231114.221320"),
              std::string::npos)
        << extension;
  }
  ::unsetenv("SOURCE_DATE_EPOCH");
}

std::string test_name(const ::testing::TestParamInfo<std::tuple<std::string, int>>& info) {
  std::string out;
  for (char c : std::get<0>(info.param)) out += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return out + (std::get<1>(info.param) == 0 ? "_step" : "_iges");
}

INSTANTIATE_TEST_SUITE_P(Bundled, CappingExchange,
                         ::testing::Combine(::testing::ValuesIn(capping_shape_names()), ::testing::Values(0, 1)),
                         test_name);

}  // namespace
}  // namespace cadnurbs::test
