// measure_deviation: exact answers on simple configurations, and it sees a displaced vertex.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/measure/measure_deviation.hpp"
#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "analysis_shapes.hpp"
#include "core/geometry_error.hpp"

namespace cadnurbs {
namespace {

TriangleMesh square(double size, double z) {
  TriangleMesh m;
  m.positions = {{0, 0, z}, {size, 0, z}, {size, size, z}, {0, size, z}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

TEST(MeasureDeviation, OffsetPlaneIsMeasuredBothWays) {
  TrimmedSurface plane = test::trimmed_square(100, 0.4, 0.15);
  plane.loops.clear();  // the whole square
  const DeviationMeasure m = measure_deviation(square(100, 0.3), plane, {2.0});
  EXPECT_NEAR(m.mesh_to_surface.max, 0.3, 1e-9);
  EXPECT_NEAR(m.surface_to_mesh.max, 0.3, 1e-9);
  EXPECT_NEAR(m.overall.rms, 0.3, 1e-9);
  EXPECT_GT(m.mesh_to_surface.samples, 100);
  EXPECT_GT(m.surface_to_mesh.samples, 100);
}

TEST(MeasureDeviation, RespectsTrimming) {
  // The whole square against the annulus: the square's corner is sqrt(2) * 50 - 40 from the outer
  // circle, its centre 15 from the hole's edge; the annulus lies on the square.
  const DeviationMeasure m = measure_deviation(square(100, 0), test::trimmed_square(100, 0.4, 0.15), {1.0});
  EXPECT_NEAR(m.mesh_to_surface.max, std::sqrt(2.0) * 50 - 40, 1e-6);
  EXPECT_NEAR(m.surface_to_mesh.max, 0.0, 1e-9);
}

TEST(MeasureDeviation, SeesADisplacedVertex) {
  const TrimmedSurface ball = test::sphere(50);
  TriangleMesh mesh = tessellate_to_deviation(ball, 0.1);
  const DeviationMeasure before = measure_deviation(mesh, ball);
  EXPECT_LE(before.overall.max, 0.1);
  // Push one vertex 0.5 mm outward, and one 0.5 mm inward elsewhere: both directions see them.
  mesh.positions[mesh.positions.size() / 3] *= (50.5 / 50.0);
  const DeviationMeasure out = measure_deviation(mesh, ball);
  EXPECT_NEAR(out.mesh_to_surface.max, 0.5, 1e-6);
  mesh.positions[mesh.positions.size() / 3] *= (49.5 / 50.5);
  const DeviationMeasure in = measure_deviation(mesh, ball);
  EXPECT_NEAR(in.mesh_to_surface.max, 0.5, 1e-6);
  EXPECT_GT(in.surface_to_mesh.max, 0.3);
}

TEST(MeasureDeviation, RefusesAnEmptyMesh) {
  EXPECT_THROW(measure_deviation(TriangleMesh{}, test::sphere(1)), GeometryError);
}

}  // namespace
}  // namespace cadnurbs
