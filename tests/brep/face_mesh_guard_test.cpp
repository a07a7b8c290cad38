// face_mesh_guard: the faces BRepMesh is not given (it can loop on them without end), and the ordinary
// faces it is.
#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopoDS.hxx>
#include <gp_Pln.hxx>

#include "formats/brep/face_mesh_guard.hpp"

namespace cadnurbs {
namespace {

// The unit square as a rational bilinear B-spline face whose corner (1, 1) has weight `w`.
TopoDS_Face weighted_square(double w) {
  TColgp_Array2OfPnt poles(1, 2, 1, 2);
  TColStd_Array2OfReal weights(1, 2, 1, 2);
  for (int i = 1; i <= 2; ++i)
    for (int j = 1; j <= 2; ++j) {
      poles(i, j) = gp_Pnt(i - 1, j - 1, 0);
      weights(i, j) = i == 2 && j == 2 ? w : 1.0;
    }
  TColStd_Array1OfReal knots(1, 2);
  knots(1) = 0;
  knots(2) = 1;
  TColStd_Array1OfInteger multiplicities(1, 2);
  multiplicities.Init(2);
  Handle(Geom_BSplineSurface) surface = new Geom_BSplineSurface(poles, weights, knots, knots, multiplicities, multiplicities, 1, 1);
  return BRepBuilderAPI_MakeFace(surface, 1e-7);
}

TEST(FaceMeshGuard, AnOrdinaryFaceMayBeMeshed) {
  EXPECT_EQ(why_not_meshable(weighted_square(2.0)), "");
  EXPECT_EQ(why_not_meshable(BRepBuilderAPI_MakeFace(gp_Pln(), -1e14, 1e14, 0, 1)), "");
}

TEST(FaceMeshGuard, WeightsSpreadBeyond1e10AreRefused) {
  EXPECT_EQ(why_not_meshable(weighted_square(1e12)), "its surface has weights spread by more than 1e10 (1 to 1e+12)");
  EXPECT_EQ(why_not_meshable(weighted_square(1e-11)), "its surface has weights spread by more than 1e10 (1e-11 to 1)");
}

TEST(FaceMeshGuard, AFaceBeyond1e15IsRefused) {
  gp_Trsf far;
  far.SetTranslation(gp_Vec(0, 0, 2e15));
  const TopoDS_Shape moved = BRepBuilderAPI_Transform(BRepBuilderAPI_MakeFace(gp_Pln(), 0, 1, 0, 1), far, true);
  EXPECT_EQ(why_not_meshable(TopoDS::Face(moved)), "it reaches beyond ±1e15 model units");
}

}  // namespace
}  // namespace cadnurbs
