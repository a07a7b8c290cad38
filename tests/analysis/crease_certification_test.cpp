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

// A piece of a triangle cut at a C0 knot line is bounded by the patch it lies in. hammer.iges has a face
// whose trim runs along u = 0 while the C0 knot lies at -2.2e-15, with a patch 0.003 wide beyond it whose
// second derivatives are 70 times its neighbour's: the cut's interpolated corners strayed an ulp across the
// line, took that patch's bound, and its .cnb at 1 mm meshed to 319,767 triangles, 157,778 uncertified.
TEST(CreaseCertification, APieceCutAtAKnotLineIsBoundedByItsOwnPatch) {
  TrimmedSurface face;
  NurbsSurface& s = face.surface;
  s.u_order = s.v_order = 3;
  s.u_count = 5, s.v_count = 3;
  const double knot = -0x1p-49;  // the C0 line, just left of the trim's u = 0
  s.u_knots = {-1, -1, -1, knot, knot, 0.003, 0.003, 0.003};
  s.v_knots = {0, 0, 0, 1, 1, 1};
  for (int j = 0; j < 3; ++j)
    for (const Eigen::Vector3d& p : {Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(-0.5, 0, 0.3), Eigen::Vector3d(0, 0, 0),
                                     Eigen::Vector3d(40, 0, 200), Eigen::Vector3d(0, 0, -200)})
      s.points.push_back(p + Eigen::Vector3d(0, 0.5 * j, 0.05 * j * j));
  face.loops.push_back({{Polyline2D{{{-1, 0}, {0, 0}, {0, 1}, {-1, 1}, {-1, 0}}}}, {}});
  TessellationReport report;
  const TriangleMesh mesh = tessellate_to_deviation(face, 0.001, &report);
  EXPECT_EQ(report.uncertified_triangles, 0);
  EXPECT_LT(mesh.triangles.size(), 5000u);
  const DeviationMeasure m = measure_deviation(mesh, face);
  EXPECT_LE(m.overall.max, 0.001);
}

}  // namespace
}  // namespace cadnurbs
