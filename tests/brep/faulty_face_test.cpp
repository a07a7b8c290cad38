// Faces with the faults real files have (a loop that bounds no area, a loop a hair outside its surface's
// domain, a loop crossing itself, a loop that does not close), built with OCCT's builders, written as
// STEP and run through the real `cadnurbs convert`: the file converts, the face is repaired or meshed,
// stderr says which, and `-o x.x3dv` and `--mesh` treat it the same way. (OCCT's STEP reader heals the
// last two itself; repair_trimming_loops_test covers our refusal of a crossing loop.)
#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepLib.hxx>
#include <GCE2d_MakeSegment.hxx>
#include <Geom_BSplineSurface.hxx>
#include <STEPControl_Writer.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <cstdlib>
#include <gp_Pln.hxx>
#include <sstream>

#include "formats/common/file_io.hpp"
#include "temporary_folder.hpp"

namespace cadnurbs::test {
namespace {

struct CommandResult {
  int status;
  std::string out, err;
};

class FaultyFace : public ::testing::Test {
 protected:
  CommandResult convert(const std::string& arguments) {
    const std::string out = folder_.file("stdout.txt"), err = folder_.file("stderr.txt");
    const int status = std::system((std::string(CADNURBS_EXE) + " convert " + arguments + " >" + out + " 2>" + err).c_str());
    return {WEXITSTATUS(status), read_file(out), read_file(err)};
  }
  std::string write_step(const TopoDS_Shape& shape, const std::string& name) {
    STEPControl_Writer writer;
    EXPECT_EQ(writer.Transfer(shape, STEPControl_AsIs), IFSelect_RetDone);
    const std::string path = folder_.file(name + ".step");
    EXPECT_EQ(writer.Write(path.c_str()), IFSelect_RetDone);
    return path;
  }
  // Converts `step` to .x3dv and with --mesh (with OpenCASCADE's reader, whose repairs these cases test,
  // unless `reader` says otherwise); both must succeed and print the same account of the face (the lines
  // naming the input); returns it.
  std::string account_of(const std::string& step, const std::string& reader = "--reader occt") {
    const CommandResult nurbs = convert(step + " " + reader + " -o " + folder_.file("out.x3dv"));
    EXPECT_EQ(nurbs.status, 0) << nurbs.err;
    const CommandResult mesh = convert(step + " " + reader + " --mesh -o " + folder_.file("out.stl"));
    EXPECT_EQ(mesh.status, 0) << mesh.err;
    EXPECT_EQ(nurbs.err, mesh.err);
    // And our own file of it reads back and meshes.
    const CommandResult again = convert(folder_.file("out.x3dv") + " --mesh -o " + folder_.file("again.stl"));
    EXPECT_EQ(again.status, 0) << again.err;
    return nurbs.err;
  }
  // The total area `cadnurbs info` prints for a file, as printed.
  std::string area_of(const std::string& path) {
    const std::string out = folder_.file("info.txt");
    std::system((std::string(CADNURBS_EXE) + " info " + path + " >" + out + " 2>&1").c_str());
    const std::string printed = read_file(out);
    const size_t at = printed.find("total area: ");
    if (at == std::string::npos) return "(none) " + printed;
    std::istringstream in(printed.substr(at + 12));
    std::string value;
    in >> value;
    return value;
  }
  TemporaryFolder folder_;
};

TopoDS_Wire polygon(std::initializer_list<gp_Pnt> points, bool close = true) {
  BRepBuilderAPI_MakePolygon make;
  for (const auto& p : points) make.Add(p);
  if (close) make.Close();
  return make.Wire();
}

TEST_F(FaultyFace, ALoopThatBoundsNoAreaIsDropped) {
  BRepBuilderAPI_MakeFace make(gp_Pln(), polygon({{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}}));
  make.Add(polygon({{3, 3, 0}, {6, 3, 0}, {8, 3, 0}}));  // collinear: a hole of no area
  ASSERT_TRUE(make.IsDone());
  const std::string step = write_step(make.Face(), "no_area");
  const std::string account = account_of(step);
  EXPECT_EQ(account.rfind(step + ": ", 0), 0u) << account;
  EXPECT_NE(account.find(" face 1 (Plane): trimming loop 1 bounds no area: dropped\n"), std::string::npos) << account;
  EXPECT_EQ(area_of(folder_.file("again.stl")), "100");
}

TEST_F(FaultyFace, ALoopCrossingItselfIsSplitByTheStepReader) {
  // A figure of eight in the plane z = 0.
  const TopoDS_Wire eight = polygon({{0, 0, 0}, {10, 10, 0}, {10, 0, 0}, {0, 10, 0}});
  BRepBuilderAPI_MakeFace make(gp_Pln(), eight);
  ASSERT_TRUE(make.IsDone());
  const std::string step = write_step(make.Face(), "eight");
  EXPECT_EQ(account_of(step), "");
  // Two triangles of 25 mm^2 each, nothing covered twice.
  EXPECT_EQ(area_of(folder_.file("again.stl")), "50");
  // Our own reader keeps the loop as the file has it, which the one check of loops refuses (its two lobes
  // cancel: no signed area): the file goes to OpenCASCADE, and the command says which face sent it there.
  const std::string account = account_of(step, "");
  EXPECT_EQ(account.rfind(step + ": read by OpenCASCADE: our STEP reader stopped at #", 0), 0u) << account;
  EXPECT_NE(account.find(" ADVANCED_FACE: every trimming loop bounds no area: the face has no area\n"), std::string::npos)
      << account;
  EXPECT_EQ(area_of(folder_.file("again.stl")), "50");
}

// A biquadratic dome over [0, 1]^2 with a rectangle trimmed on it whose lower side runs at v = -1e-9,
// outside the surface's domain.
TEST_F(FaultyFace, ALoopAHairOutsideTheDomainIsMovedOntoIt) {
  TColgp_Array2OfPnt poles(1, 3, 1, 3);
  for (int i = 1; i <= 3; ++i)
    for (int j = 1; j <= 3; ++j) poles(i, j) = gp_Pnt(5.0 * (i - 1), 5.0 * (j - 1), (i == 2 && j == 2) ? 4.0 : 0.0);
  TColStd_Array1OfReal knots(1, 2);
  knots(1) = 0, knots(2) = 1;
  TColStd_Array1OfInteger mults(1, 2);
  mults(1) = mults(2) = 3;
  Handle(Geom_BSplineSurface) dome = new Geom_BSplineSurface(poles, knots, knots, mults, mults, 2, 2);
  const double v0 = -1e-9;
  const gp_Pnt2d corners[4] = {{0.2, v0}, {0.8, v0}, {0.8, 0.5}, {0.2, 0.5}};
  BRepBuilderAPI_MakeWire wire;
  for (int k = 0; k < 4; ++k) {
    Handle(Geom2d_TrimmedCurve) side = GCE2d_MakeSegment(corners[k], corners[(k + 1) % 4]);
    wire.Add(BRepBuilderAPI_MakeEdge(side, dome).Edge());
  }
  ASSERT_TRUE(wire.IsDone());
  TopoDS_Wire w = wire.Wire();
  BRepLib::BuildCurves3d(w);
  BRepBuilderAPI_MakeFace make(dome, w, true);
  ASSERT_TRUE(make.IsDone());
  const std::string step = write_step(make.Face(), "outside");
  const std::string account = account_of(step);
  EXPECT_EQ(account.rfind(step + ": ", 0), 0u) << account;
  EXPECT_NE(account.find(" face 1 (BSplineSurface): trimming loop 0 left the surface's domain by 1e-09 of its size: "),
            std::string::npos)
      << account;
  EXPECT_NE(account.find(" points moved onto the domain's edge\n"), std::string::npos) << account;
}

TEST_F(FaultyFace, ALoopThatDoesNotCloseIsClosedByTheStepReader) {
  // The wire stops 1 mm short of its start.
  const TopoDS_Wire open = polygon({{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}, {0, 1, 0}}, false);
  BRepBuilderAPI_MakeFace make(gp_Pln(), open);
  ASSERT_TRUE(make.IsDone());
  const std::string step = write_step(make.Face(), "open");
  EXPECT_EQ(account_of(step), "");
  EXPECT_EQ(area_of(folder_.file("again.stl")), "100");
}

}  // namespace
}  // namespace cadnurbs::test
