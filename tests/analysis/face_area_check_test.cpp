// check_face_area: a mesh within D of its face stays within the allowance; a mesh covering part of the
// face twice does not.
#include <gtest/gtest.h>

#include "analysis/measure/face_area_check.hpp"
#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "analysis_shapes.hpp"

namespace cadnurbs {
namespace {

TEST(FaceAreaCheck, CertifiedMeshesStayWithinTheAllowance) {
  // An annulus (its hole polygon adds area, its rim polygon loses some) and a cylinder (chords lose
  // about D / 3r), coarse and fine.
  for (double d : {0.5, 0.05}) {
    const TrimmedSurface annulus = test::trimmed_square(10, 0.45, 0.4);
    const FaceAreaCheck flat = check_face_area(annulus, tessellate_to_deviation(annulus, d), d);
    EXPECT_FALSE(flat.beyond()) << "D " << d << ": " << flat.mesh_area << " against " << flat.area;
    const TrimmedSurface cylinder = test::quarter_cylinder(2, 5);
    const FaceAreaCheck round = check_face_area(cylinder, tessellate_to_deviation(cylinder, d), d);
    EXPECT_FALSE(round.beyond()) << "D " << d << ": " << round.mesh_area << " against " << round.area;
    EXPECT_LT(round.mesh_area, round.area);  // chords cut corners
  }
}

TEST(FaceAreaCheck, APartCoveredTwiceIsBeyond) {
  const TrimmedSurface cylinder = test::quarter_cylinder(2, 5);
  const double d = 0.01;
  TriangleMesh mesh = tessellate_to_deviation(cylinder, d);
  const FaceAreaCheck once = check_face_area(cylinder, mesh, d);
  EXPECT_FALSE(once.beyond());
  // A tenth of the triangles again, with their own vertices (a fold that welding would not see).
  TriangleMesh again;
  again.positions = mesh.positions;
  for (size_t t = 0; t < mesh.triangles.size() / 10; ++t) again.triangles.push_back(mesh.triangles[t]);
  append(mesh, again);
  const FaceAreaCheck twice = check_face_area(cylinder, mesh, d);
  EXPECT_TRUE(twice.beyond()) << twice.mesh_area << " against " << twice.area << ", allowance " << twice.allowance;
}

}  // namespace
}  // namespace cadnurbs
