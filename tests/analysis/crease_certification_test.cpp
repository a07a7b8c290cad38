// Certification of a triangle across a crease between two flat pieces: the bundled capping-moulded's
// plow (a 32 x 6 mm groove in the underside) has a side wall and a ceiling that are both planes along
// the straight legs of the path. Its certified mesh at D <= 0.5 had triangles from the eased edge
// (z = 1) straight to the middle of the ceiling (z = 6), certified although the plow's corner at
// (16, 6) of the profile lay 4.77 mm off them: the pieces of a triangle cut at a C0 knot line had
// their corners' errors taken as D, and a flat piece (bound 0) then passed without a sample.
#include <gtest/gtest.h>

#include "analysis/measure/measure_deviation.hpp"
#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "formats/vrml/vrml_reader.hpp"

namespace cadnurbs {
namespace {

TEST(CreaseCertification, MouldedCappingPlowCornerIsKeptWithinAQuarterMillimetre) {
  const Scene scene = read_vrml(CADNURBS_SOURCE_DIR "/samples/capping-moulded.x3dv");
  const TrimmedSurface* body = nullptr;
  for_each_shape(scene, [&](const Shape& shape, const Eigen::Affine3d&, const Colour&) {
    if (display_name(shape) == "body") body = std::get_if<TrimmedSurface>(&shape.geometry);
  });
  ASSERT_NE(body, nullptr);
  TessellationReport report;
  const TriangleMesh mesh = tessellate_to_deviation(*body, 0.25, &report);
  EXPECT_EQ(report.uncertified_triangles, 0);
  const DeviationMeasure m = measure_deviation(mesh, *body);
  EXPECT_LE(m.mesh_to_surface.max, 0.25);
  EXPECT_LE(m.surface_to_mesh.max, 0.25);
  EXPECT_GT(m.overall.max, 0.15);
}

}  // namespace
}  // namespace cadnurbs
