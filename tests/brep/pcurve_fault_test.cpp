// A B-rep fault that OCCT's STEP and IGES readers heal before we see it, so it is built in memory and
// given to the B-rep path directly: a hemisphere (two faces, the dome and the disk) whose shared
// circle's pcurve on the disk is moved 10 D sideways, so that the disk's trim no longer runs along the
// edge its neighbour has (issue 9).
#include <gtest/gtest.h>

#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom_Plane.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <cmath>
#include <vector>

#include "analysis/mesh/count_boundary_edges.hpp"
#include "analysis/mesh/scene_triangles.hpp"
#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "analysis/mesh/weld_exact.hpp"
#include "formats/brep/rebuild_stray_pcurves.hpp"
#include "formats/brep/xcaf_to_scene.hpp"
#include "read_back_watertight.hpp"

namespace cadnurbs::test {
namespace {

constexpr double kRadius = 10.0, kDeviation = 0.03;

// The hemisphere with the disk's pcurve of the circle moved by `shift` along u.
TopoDS_Shape hemisphere_with_pcurve_moved(double shift) {
  TopoDS_Shape solid = BRepPrimAPI_MakeSphere(kRadius, 0.0, M_PI / 2).Solid();
  for (TopExp_Explorer faces(solid, TopAbs_FACE); faces.More(); faces.Next()) {
    const TopoDS_Face& disk = TopoDS::Face(faces.Current());
    if (BRep_Tool::Surface(disk)->DynamicType() != STANDARD_TYPE(Geom_Plane)) continue;
    for (TopExp_Explorer edges(disk, TopAbs_EDGE); edges.More(); edges.Next()) {
      const TopoDS_Edge& circle = TopoDS::Edge(edges.Current());
      double first = 0, last = 0;
      const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(circle, disk, first, last);
      const Handle(Geom2d_Curve) off = Handle(Geom2d_Curve)::DownCast(pcurve->Translated(gp_Vec2d(shift, 0)));
      BRep_Builder().UpdateEdge(circle, off, disk, BRep_Tool::Tolerance(circle));
    }
  }
  return solid;
}

TEST(PcurveFault, APcurveTenDeviationsOffItsEdgeIsRebuiltFromTheEdge) {
  const TopoDS_Shape solid = hemisphere_with_pcurve_moved(10 * kDeviation);
  // The fault is there: the disk's pcurve of the circle is 10 D from the circle.
  std::vector<double> strays;
  for (TopExp_Explorer faces(solid, TopAbs_FACE); faces.More(); faces.Next())
    for (TopExp_Explorer edges(faces.Current(), TopAbs_EDGE); edges.More(); edges.Next()) {
      const double d = pcurve_stray_distance(TopoDS::Edge(edges.Current()), TopoDS::Face(faces.Current()));
      if (d > 0.1 * kDeviation) strays.push_back(d);
    }
  ASSERT_EQ(strays.size(), 1u);
  EXPECT_NEAR(strays[0], 10 * kDeviation, 1e-9);

  const BrepTranslation translated = shape_to_scene(solid, "hemisphere");
  EXPECT_TRUE(translated.fallbacks.empty());
  ASSERT_EQ(translated.repairs.size(), 1u);
  EXPECT_EQ(translated.repairs[0].rfind("hemisphere face 2 (Plane): pcurve of edge ", 0), 0u) << translated.repairs[0];
  EXPECT_NE(translated.repairs[0].find(" was 0.3 from its 3D curve: rebuilt from it (now "), std::string::npos)
      << translated.repairs[0];

  // Meshed from the B-rep: closed, every triangle certified, the disk's area pi r^2 (a trim off by
  // 0.3 would still give pi r^2: the area alone cannot see the fault).
  TessellationReport report;
  const Scene meshed = tessellate_to_deviation(translated.scene, kDeviation, &report, /*check_face_areas=*/true);
  const EdgeCounts edges = count_boundary_edges(weld_exact(scene_triangles(meshed)));
  EXPECT_EQ(edges.boundary, 0);
  EXPECT_EQ(edges.non_manifold, 0);
  EXPECT_EQ(report.uncertified_triangles, 0);
  EXPECT_EQ(report.unshared_edge_uses, 0);
  EXPECT_EQ(report.faces_beyond_area_allowance, 0);
  // And from our own files of it (x3dv compact and exact, wrl, x3d), read back and sewn: closed too.
  check_read_back_watertight(translated.scene, "hemisphere");
}

// The control: the same hemisphere without the fault has nothing to rebuild.
TEST(PcurveFault, AHemisphereWithoutTheFaultIsLeftAlone) {
  const BrepTranslation translated = shape_to_scene(hemisphere_with_pcurve_moved(0.0), "hemisphere");
  EXPECT_TRUE(translated.repairs.empty());
  EXPECT_TRUE(translated.fallbacks.empty());
}

}  // namespace
}  // namespace cadnurbs::test
