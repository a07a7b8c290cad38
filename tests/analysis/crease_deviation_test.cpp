// measure_deviation across a crease: the bundled capping-post's body is one surface whose profile has
// corners (C0 knots, here every knot of u), and its certified mesh at D cuts them by chords. A point of
// the mesh beside the flat of y = +-60 once measured 2.67 mm at D = 1 (2.34 at D = 0.25): its nearest
// reference triangle ran across the corner at z = 30, Newton started on the cove's side of it and found
// the cove's own foot. Measured independently (the body is a prism: distance to the densely sampled
// profile, or to the lids' planes inside it), the mesh lies within 0.75 mm of the surface at D = 1 and
// within 0.19 mm at D = 0.25.
#include <gtest/gtest.h>

#include <string>

#include "analysis/measure/measure_deviation.hpp"
#include "analysis/mesh/scene_triangles.hpp"
#include "analysis/sewing/sew_faces.hpp"
#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "core/bounding_box.hpp"
#include "formats/vrml/vrml_reader.hpp"

namespace cadnurbs {
namespace {

const Scene& capping_post() {
  static const Scene scene = read_vrml(CADNURBS_SOURCE_DIR "/samples/capping-post.x3dv");
  return scene;
}

// The mesh convert --mesh writes for a VRML/X3D input: sewn (the file names no edges), then certified.
DeviationMeasure capping_post_measured_at(double max_deviation) {
  const Scene& scene = capping_post();
  const Scene sewn = sew_faces(scene, sewing_tolerance(scene_bounding_box(scene).diagonal().norm(), max_deviation));
  TessellationReport report;
  const TriangleMesh mesh = scene_triangles(tessellate_to_deviation(sewn, max_deviation, &report));
  EXPECT_EQ(report.uncertified_triangles, 0);
  EXPECT_LE(report.certified_deviation, max_deviation);
  return measure_deviation(mesh, scene);
}

TEST(CreaseDeviation, CappingPostMeshMeasuresWithinOneMillimetre) {
  const DeviationMeasure m = capping_post_measured_at(1.0);
  EXPECT_LE(m.mesh_to_surface.max, 1.0);
  EXPECT_LE(m.surface_to_mesh.max, 1.0);
  // The measure sees the chords' sagittas: the profile's corners are chord ends, and the body's
  // chords between them lie up to 0.76 mm off the surface.
  EXPECT_GT(m.surface_to_mesh.max, 0.7);
}

TEST(CreaseDeviation, CappingPostMeshMeasuresWithinAQuarterMillimetre) {
  const DeviationMeasure m = capping_post_measured_at(0.25);
  EXPECT_LE(m.mesh_to_surface.max, 0.25);
  EXPECT_LE(m.surface_to_mesh.max, 0.25);
  EXPECT_GT(m.overall.max, 0.15);
}

// The body alone (other sample spacing, so other reference triangles): one of them spans two corners
// (u 9.875 to 11, corners at 10 and 11), and the foot lies on the flat between them (it measured 2.99).
TEST(CreaseDeviation, ReferenceTriangleOverTwoCornersFindsTheFlatBetween) {
  const TrimmedSurface* body = nullptr;
  for_each_shape(capping_post(), [&](const Shape& shape, const Eigen::Affine3d&, const Colour&) {
    if (display_name(shape) == "body") body = std::get_if<TrimmedSurface>(&shape.geometry);
  });
  ASSERT_NE(body, nullptr);
  const DeviationMeasure m = measure_deviation(tessellate_to_deviation(*body, 1.0), *body);
  EXPECT_LE(m.mesh_to_surface.max, 1.0);
  EXPECT_GT(m.mesh_to_surface.max, 0.5);
}

}  // namespace
}  // namespace cadnurbs
