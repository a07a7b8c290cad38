// Faces of OCCT primitives through shape_to_scene: seams, poles, apexes, holes, reversed faces, periodic
// B-splines crossing their seam, faces rebuilt from a real part library (kicad-packages3d) whose pcurves
// miss each other by a little, and a face that cannot be converted. Areas and volumes are checked against
// the closed forms.
#include <gtest/gtest.h>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRepLib.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_Plane.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_Line.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Wire.hxx>
#include <cmath>
#include <map>

#include "analysis/measure/measure_deviation.hpp"
#include "analysis/eval/surface_evaluator.hpp"
#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "core/trim_segment_parameters.hpp"
#include "formats/brep/xcaf_to_scene.hpp"
#include "occt_reference.hpp"
#include "trimmed_measure.hpp"

namespace cadnurbs::test {
namespace {

constexpr double pi = 3.14159265358979323846;
// The independent integration (trimmed_measure) is good to a few 1e-6; a wrong conversion is far off.
constexpr double close = 1e-5;

struct Totals {
  int nurbs = 0, meshes = 0;
  SurfaceMeasure measure;
};

Totals totals(const BrepTranslation& t) {
  Totals out;
  for_each_shape(t.scene, [&](const Shape& shape, const Eigen::Affine3d& world, const Colour&) {
    if (const auto* s = std::get_if<TrimmedSurface>(&shape.geometry)) {
      ++out.nurbs;
      EXPECT_NO_THROW(validate(*s, shape.name));
      for (size_t l = 0; l < s->loops.size(); ++l) EXPECT_TRUE(region_left_of_loop(*s, l)) << shape.name << " loop " << l;
      const auto m = measure_trimmed_surface(*s, world);
      out.measure.area += m.area;
      out.measure.volume += m.volume;
    } else {
      ++out.meshes;
    }
  });
  return out;
}

// Every edge of a closed solid is used twice, once each way; degenerated edges once.
void expect_closed_edge_uses(const BrepTranslation& t) {
  std::map<int, std::pair<int, int>> uses;  // edge -> (uses, against)
  for_each_shape(t.scene, [&](const Shape& shape, const Eigen::Affine3d&, const Colour&) {
    if (const auto* s = std::get_if<TrimmedSurface>(&shape.geometry))
      for (const auto& loop : s->loops)
        for (const auto& ref : loop.edges) {
          ASSERT_GE(ref.edge, 0);
          ++uses[ref.edge].first;
          uses[ref.edge].second += ref.reversed ? 1 : 0;
        }
  });
  ASSERT_EQ(uses.size(), t.degenerated_edges.size());
  for (const auto& [edge, u] : uses) {
    if (t.degenerated_edges[edge]) {
      EXPECT_EQ(u.first, 1) << "degenerated edge " << edge;
    } else {
      EXPECT_EQ(u.first, 2) << "edge " << edge;
      EXPECT_EQ(u.second, 1) << "edge " << edge << " is not used once each way";
    }
  }
}

TEST(FaceConversion, CylinderSeamIsOneEdgeUsedBothWays) {
  const double r = 10, h = 20;
  const BrepTranslation t = shape_to_scene(BRepPrimAPI_MakeCylinder(r, h).Shape(), "cylinder");
  ASSERT_EQ(t.face_count, 3);
  const Totals sum = totals(t);
  EXPECT_EQ(sum.nurbs, 3);
  EXPECT_NEAR(sum.measure.area, 2 * pi * r * h + 2 * pi * r * r, close * sum.measure.area);
  EXPECT_NEAR(sum.measure.volume, pi * r * r * h, close * sum.measure.volume);
  expect_closed_edge_uses(t);
  // The lateral face: four segments, the seam twice.
  const auto& lateral = std::get<TrimmedSurface>(t.scene.root.shapes[0].geometry);
  ASSERT_EQ(lateral.loops.size(), 1u);
  std::map<int, int> count;
  for (const auto& ref : lateral.loops[0].edges) ++count[ref.edge];
  int twice = 0;
  for (const auto& [edge, n] : count) twice += n == 2 ? 1 : 0;
  EXPECT_EQ(twice, 1) << "one seam edge used twice by the lateral face";
}

TEST(FaceConversion, SpherePolesAreDegeneratedEdges) {
  const double r = 5;
  const BrepTranslation t = shape_to_scene(BRepPrimAPI_MakeSphere(r).Shape(), "sphere");
  ASSERT_EQ(t.face_count, 1);
  const Totals sum = totals(t);
  EXPECT_EQ(sum.meshes, 0);
  EXPECT_NEAR(sum.measure.area, 4 * pi * r * r, close * sum.measure.area);
  EXPECT_NEAR(sum.measure.volume, 4.0 / 3 * pi * r * r * r, close * sum.measure.volume);
  int degenerated = 0;
  for (bool d : t.degenerated_edges) degenerated += d ? 1 : 0;
  EXPECT_EQ(degenerated, 2);
  expect_closed_edge_uses(t);
}

TEST(FaceConversion, ConeApexAndTorus) {
  const BrepTranslation cone = shape_to_scene(BRepPrimAPI_MakeCone(5, 0, 12).Shape(), "cone");
  const Totals c = totals(cone);
  EXPECT_EQ(c.meshes, 0);
  const double slant = std::hypot(5.0, 12.0);
  EXPECT_NEAR(c.measure.area, pi * 5 * slant + pi * 25, close * c.measure.area);
  EXPECT_NEAR(c.measure.volume, pi * 25 * 12 / 3, close * c.measure.volume);
  expect_closed_edge_uses(cone);

  const BrepTranslation torus = shape_to_scene(BRepPrimAPI_MakeTorus(20, 4).Shape(), "torus");
  const Totals s = totals(torus);
  EXPECT_EQ(s.meshes, 0);
  EXPECT_NEAR(s.measure.area, 4 * pi * pi * 20 * 4, close * s.measure.area);
  EXPECT_NEAR(s.measure.volume, 2 * pi * pi * 20 * 16, close * s.measure.volume);
  expect_closed_edge_uses(torus);
}

TEST(FaceConversion, HolesRunClockwiseAndNormalsPointOut) {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(40, 30, 20).Shape();
  const TopoDS_Shape drill = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(20, 15, -5), gp_Dir(0, 0, 1)), 6, 30).Shape();
  const TopoDS_Shape part = BRepAlgoAPI_Cut(box, drill).Shape();
  const BrepTranslation t = shape_to_scene(part, "drilled");
  const Totals sum = totals(t);
  EXPECT_EQ(sum.meshes, 0);
  EXPECT_NEAR(sum.measure.area, 2 * (40 * 30 + 40 * 20 + 30 * 20) - 2 * pi * 36 + 2 * pi * 6 * 20, close * sum.measure.area);
  EXPECT_NEAR(sum.measure.volume, 40 * 30 * 20 - pi * 36 * 20, close * sum.measure.volume);
  expect_closed_edge_uses(t);
  int holes = 0;
  for_each_shape(t.scene, [&](const Shape& shape, const Eigen::Affine3d&, const Colour&) {
    const auto& s = std::get<TrimmedSurface>(shape.geometry);
    for (const auto& loop : s.loops) holes += loop_signed_area(loop) < 0 ? 1 : 0;
    // Outward: from the box's centre towards the face (the hole's wall faces the axis).
    const NurbsCurve& first = std::get<NurbsCurve>(s.loops[0].segments[0]);
    const Eigen::Vector2d uv = curve_point(first, 0.5 * (first.domain_start() + first.domain_end())).head<2>();
    const Eigen::Vector3d p = surface_point(s.surface, uv.x(), uv.y()), n = surface_normal(s.surface, uv.x(), uv.y());
    const Eigen::Vector3d radial(p.x() - 20, p.y() - 15, 0);
    const bool wall = std::abs(radial.norm() - 6) < 1e-6 && p.z() > 1e-6 && p.z() < 20 - 1e-6;
    if (wall) EXPECT_LT(n.dot(radial), 0) << shape.name;
    else EXPECT_GT(n.dot(p - Eigen::Vector3d(20, 15, 10)), 0) << shape.name;
  });
  EXPECT_EQ(holes, 2) << "top and bottom each have one clockwise hole";
}

TEST(FaceConversion, PeriodicBSplineFaceAcrossItsSeam) {
  // A periodic B-spline cylinder, and a face on it from u = -1 to 1: across the parameterization's seam.
  Handle(Geom_Surface) cylinder = new Geom_CylindricalSurface(gp_Ax3(), 7.0);
  Handle(Geom_BSplineSurface) bspline =
      GeomConvert::SurfaceToBSplineSurface(new Geom_RectangularTrimmedSurface(cylinder, 0.0, 2 * pi, 0.0, 10.0));
  if (!bspline->IsUPeriodic()) bspline->SetUPeriodic();
  ASSERT_TRUE(bspline->IsUPeriodic());
  Standard_Real u0, u1, v0, v1;
  bspline->Bounds(u0, u1, v0, v1);
  const double a = u0 - 0.15 * (u1 - u0), b = u0 + 0.2 * (u1 - u0);
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(bspline, a, b, 0, 10, 1e-7).Face();
  const OcctReference reference = occt_reference(face);
  const BrepTranslation t = shape_to_scene(face, "patch");
  ASSERT_EQ(t.face_count, 1);
  const Totals sum = totals(t);
  EXPECT_EQ(sum.meshes, 0);
  EXPECT_NEAR(sum.measure.area, reference.adaptive_area, close * reference.adaptive_area);
  const auto& s = std::get<TrimmedSurface>(t.scene.root.shapes[0].geometry);
  for (const auto& segment : s.loops[0].segments)
    for (const Eigen::Vector2d& p : {segment_start(segment), segment_end(segment)}) {
      EXPECT_GE(p.x(), s.surface.u_start() - 1e-9);
      EXPECT_LE(p.x(), s.surface.u_end() + 1e-9);
    }
}

TEST(FaceConversion, HelixEdgeOnAHalfCylinderKeepsItsPath) {
  // A triangle on a half cylinder (Ventilator.stp's range, u from 3.07749 to 2 pi): two iso-line sides
  // and a helix, a straight pcurve across u. The B-spline's u is not the angle, so the helix must not
  // pass unchanged (it did: a 5-point identity test of the parameter map missed the difference).
  const double r = 9.0, u0 = 3.07749, u1 = 2 * pi, v0 = -6.95, v1 = 3.5;
  Handle(Geom_CylindricalSurface) cylinder = new Geom_CylindricalSurface(gp_Ax3(), r);
  BRep_Builder builder;
  TopoDS_Face face;
  builder.MakeFace(face, cylinder, 1e-7);
  const std::array<gp_Pnt2d, 4> corners = {gp_Pnt2d(u0, v0), gp_Pnt2d(u1, v0), gp_Pnt2d(u1, v1), gp_Pnt2d(u0, v0)};
  TopoDS_Wire wire;
  builder.MakeWire(wire);
  std::vector<TopoDS_Vertex> vertices;
  for (int i = 0; i < 3; ++i) vertices.push_back(BRepBuilderAPI_MakeVertex(cylinder->Value(corners[i].X(), corners[i].Y())));
  for (int i = 0; i < 3; ++i) {
    const gp_Vec2d d(corners[i], corners[i + 1]);
    BRepBuilderAPI_MakeEdge edge(new Geom2d_Line(corners[i], gp_Dir2d(d)), cylinder, vertices[i], vertices[(i + 1) % 3], 0.0,
                                 d.Magnitude());
    builder.Add(wire, edge.Edge());
  }
  builder.Add(face, wire);
  BRepLib::BuildCurves3d(face);
  const BrepTranslation t = shape_to_scene(face, "helix");
  ASSERT_EQ(t.face_count, 1);
  const Totals sum = totals(t);
  ASSERT_EQ(sum.meshes, 0);
  EXPECT_NEAR(sum.measure.area, 0.5 * r * (u1 - u0) * (v1 - v0), close * sum.measure.area);
  // Every point of the loop's image lies on one of the three sides: the helix z = v0 + (angle - u0) *
  // slope, the bottom circle, or the vertical line at u1.
  const auto& s = std::get<TrimmedSurface>(t.scene.root.shapes[0].geometry);
  const SurfaceEvaluator surface(s.surface);
  double worst = 0;
  for (const auto& segment : s.loops[0].segments)
    for (int i = 0; i <= 64; ++i) {
      const Eigen::Vector2d uv = segment_uv(segment, segment_t0(segment) + (segment_t1(segment) - segment_t0(segment)) * i / 64);
      const Eigen::Vector3d p = surface.point(uv.x(), uv.y());
      double angle = std::atan2(p.y(), p.x());
      if (angle < 0) angle += 2 * pi;
      if (angle < 1) angle += 2 * pi;  // the end at 2 pi
      const double helix = v0 + (angle - u0) * (v1 - v0) / (u1 - u0);
      const double to_side = std::min({std::abs(p.z() - helix), std::abs(p.z() - v0), r * std::abs(angle - u1)});
      worst = std::max(worst, to_side);
    }
  // NurbsConvert re-projects the helix: 1.5e-5 off here; the 5-point test left it 0.056 off.
  EXPECT_LE(worst, 1e-5 * r);
}

// Distance from p to the torus about the z axis through the origin: to the nearer of the two tube circles in
// p's meridian plane (a spindle torus's tube crosses the axis, so both count).
double off_torus(const Eigen::Vector3d& p, double major, double minor) {
  const double rho = std::hypot(p.x(), p.y());
  return std::min(std::abs(std::hypot(rho - major, p.z()) - minor), std::abs(std::hypot(rho + major, p.z()) - minor));
}

// The one face of `face`'s translation, which must be a trimmed NURBS: valid, loops the right way round,
// on the torus (R, r) about the z axis (a 41 x 41 grid of its whole surface), its tessellation at
// `deviation` within `deviation` of it with every triangle certified. Returns it and its area.
std::pair<TrimmedSurface, double> exact_torus_face(const TopoDS_Face& face, double major, double minor,
                                                   double deviation) {
  const BrepTranslation t = shape_to_scene(face, "face");
  EXPECT_EQ(t.face_count, 1);
  for (const auto& f : t.fallbacks) ADD_FAILURE() << "fell back to a mesh: " << f.reason;
  if (t.scene.root.shapes.size() != 1 || !std::holds_alternative<TrimmedSurface>(t.scene.root.shapes[0].geometry)) {
    ADD_FAILURE() << "no trimmed surface";
    return {};
  }
  const auto& s = std::get<TrimmedSurface>(t.scene.root.shapes[0].geometry);
  EXPECT_NO_THROW(validate(s, "face"));
  for (size_t l = 0; l < s.loops.size(); ++l) EXPECT_TRUE(region_left_of_loop(s, l)) << "loop " << l;
  double worst = 0;
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j <= 40; ++j) {
      const double u = s.surface.u_start() + (s.surface.u_end() - s.surface.u_start()) * i / 40;
      const double v = s.surface.v_start() + (s.surface.v_end() - s.surface.v_start()) * j / 40;
      worst = std::max(worst, off_torus(surface_point(s.surface, u, v), major, minor));
    }
  EXPECT_LE(worst, 1e-12 * (major + minor)) << "the NURBS is not the torus";
  TessellationReport report;
  const TriangleMesh mesh = tessellate_to_deviation(s, deviation, &report);
  EXPECT_EQ(report.uncertified_triangles, 0);
  EXPECT_LE(measure_deviation(mesh, s).overall.max, deviation);
  return {s, measure_trimmed_surface(s, Eigen::Affine3d::Identity()).area};
}

TEST(FaceConversion, TorusFaceOverAFullTurnStartingBelowMinusPi) {
  // R_Axial_DIN0411's lead bends: a quarter turn of a torus around its axis, a full turn around its tube
  // from v = -3.141592653589794 (2 ulps below -pi) to pi, 2 pi + 9e-16 in all. Cut to one period and
  // moved into [0, 2 pi) by a Geom_RectangularTrimmedSurface, the range came out 9e-16 longer than 2 pi
  // again, which Convert_TorusToBSplineSurface refuses; NurbsConvert (over the face's bounds) refused it
  // too, and the face became a mesh.
  const double v0 = -3.141592653589794, v1 = pi;
  ASSERT_GT(v1 - v0, 2 * pi);
  const double major = 1.2, minor = 0.4;
  const TopoDS_Face face =
      BRepBuilderAPI_MakeFace(new Geom_ToroidalSurface(gp_Ax3(), major, minor), 0, pi / 2, v0, v1, 1e-7).Face();
  const OcctReference reference = occt_reference(face);
  const double area = exact_torus_face(face, major, minor, 1e-3).second;
  EXPECT_NEAR(area, pi * pi * major * minor, close * area);  // (pi / 2) x (2 pi r) x R
  EXPECT_NEAR(area, reference.area, close * area);
}

TEST(FaceConversion, SpindleTorusFaceOverAFullTurn) {
  // A spindle torus (tube radius 0.9 above the axis distance 0.5): the tube crosses the axis. OCCT's
  // converter takes it (the circle-of-circles net is linear in the profile's poles, whatever their sign).
  const double major = 0.5, minor = 0.9, v0 = -3.141592653589794, v1 = pi;
  const TopoDS_Face face =
      BRepBuilderAPI_MakeFace(new Geom_ToroidalSurface(gp_Ax3(), major, minor), 0, pi / 2, v0, v1, 1e-7).Face();
  const OcctReference reference = occt_reference(face);
  const double area = exact_torus_face(face, major, minor, 1e-3).second;
  // (pi / 2) r times the integral of |R + r cos v| over a turn: the tube's inner part, where R + r cos v < 0,
  // lies beyond the axis.
  const double turn = std::acos(-major / minor);
  const double exact = 0.5 * pi * minor *
                       (2 * (major * turn + minor * std::sin(turn)) - 2 * (major * (pi - turn) - minor * std::sin(turn)));
  EXPECT_NEAR(reference.adaptive_area, exact, 1e-6 * exact);
  // Our integration has a kink of |Su x Sv| on the axis inside its triangles there: 6e-4 off.
  EXPECT_NEAR(area, exact, 1e-3 * exact);
}

TEST(FaceConversion, TorusSeamPcurvesAFewMicroradiansOff) {
  // L_Axial_L11.0mm_D4.5mm_P15.24mm_Horizontal_Fastron_MECC's lead bend (R 0.7, r 0.35, u a quarter turn,
  // v from pi to 3 pi: the seam on the inner equator): the seam's pcurves lie 9.65e-6 off in u and v,
  // 4.8e-6 mm in 3D, within twice the vertex tolerance 3.38e-6. BRepTools_WireExplorer allows
  // 2 x 3.38e-6 / (R + r) = 6.4e-6 in u (the speed of u on the outer equator, three times that on the
  // inner one) and stopped after the seam: "wire 1 is not connected: 1 of its 4 edges follow each other".
  const double major = 0.7, minor = 0.35, u0 = 1.5 * pi, u1 = 2 * pi, v0 = pi;
  Handle(Geom_ToroidalSurface) torus = new Geom_ToroidalSurface(gp_Ax3(), major, minor);
  BRep_Builder builder;
  const TopoDS_Vertex a = BRepBuilderAPI_MakeVertex(torus->Value(u0, v0)), b = BRepBuilderAPI_MakeVertex(torus->Value(u1, v0));
  builder.UpdateVertex(a, 3.38e-6);
  builder.UpdateVertex(b, 3.38e-6);
  auto edge = [&](const gp_Pnt2d& from, const gp_Dir2d& direction, const TopoDS_Vertex& start, const TopoDS_Vertex& end,
                  double length) {
    TopoDS_Edge e = BRepBuilderAPI_MakeEdge(new Geom2d_Line(from, direction), torus, start, end, 0, length).Edge();
    BRepLib::BuildCurves3d(e);
    return e;
  };
  const TopoDS_Edge seam = edge(gp_Pnt2d(u0, v0), gp_Dir2d(1, 0), a, b, u1 - u0);
  const TopoDS_Edge right = edge(gp_Pnt2d(u1, v0), gp_Dir2d(0, 1), b, b, 2 * pi);
  const TopoDS_Edge left = edge(gp_Pnt2d(u0, v0), gp_Dir2d(0, 1), a, a, 2 * pi);
  TopoDS_Face face;
  builder.MakeFace(face, torus, 1e-7);
  TopoDS_Wire wire;
  builder.MakeWire(wire);
  builder.Add(wire, seam);
  builder.Add(wire, right);
  builder.Add(wire, seam.Reversed());
  builder.Add(wire, left.Reversed());
  builder.Add(face, wire);
  // The seam's two pcurves (forward: v = pi, reversed: v = 3 pi), both a little off.
  const gp_Vec2d off(-9.65e-6, -9.64e-6);
  builder.UpdateEdge(seam, new Geom2d_Line(gp_Pnt2d(u0, v0).Translated(off), gp_Dir2d(1, 0)),
                     new Geom2d_Line(gp_Pnt2d(u0, v0 + 2 * pi).Translated(off), gp_Dir2d(1, 0)), face, 2.15e-6);
  builder.Range(seam, face, 0, u1 - u0);
  int explored = 0;
  for (BRepTools_WireExplorer ex(wire, face); ex.More(); ex.Next()) ++explored;
  EXPECT_LT(explored, 4) << "OCCT's explorer no longer stops here; the test no longer shows the case";
  const OcctReference reference = occt_reference(face);
  const auto [s, area] = exact_torus_face(face, major, minor, 1e-3);
  // A quarter of the torus's area, 4 pi^2 R r.
  EXPECT_NEAR(area, pi * pi * major * minor, 1e-5 * area);
  EXPECT_NEAR(area, reference.area, close * area);
  ASSERT_EQ(s.loops.size(), 1u);
  EXPECT_EQ(s.loops[0].segments.size(), 4u);
}

TEST(FaceConversion, PcurveAPeriodAwayFromItsNeighbours) {
  // L_CommonMode_Toroid_Vertical_L19.3mm...'s sliver next to a cylinder's seam: one edge's pcurve lies a
  // whole turn away from where its neighbours meet it. Here a triangle on a cylinder, u from -0.2 to 0,
  // whose helix side (from the top corner at u = 0 to the bottom one at u = -0.2) is given at u + 2 pi.
  const double r = 1.5, u0 = -0.2, height = 1.0;
  Handle(Geom_CylindricalSurface) cylinder = new Geom_CylindricalSurface(gp_Ax3(), r);
  const TopoDS_Vertex a = BRepBuilderAPI_MakeVertex(cylinder->Value(u0, 0)), b = BRepBuilderAPI_MakeVertex(cylinder->Value(0, 0)),
                      c = BRepBuilderAPI_MakeVertex(cylinder->Value(0, height));
  auto edge = [&](const gp_Pnt2d& from, const gp_Pnt2d& to, const TopoDS_Vertex& start, const TopoDS_Vertex& end) {
    const gp_Vec2d d(from, to);
    TopoDS_Edge e = BRepBuilderAPI_MakeEdge(new Geom2d_Line(from, gp_Dir2d(d)), cylinder, start, end, 0, d.Magnitude()).Edge();
    BRepLib::BuildCurves3d(e);
    return e;
  };
  BRep_Builder builder;
  TopoDS_Wire wire;
  builder.MakeWire(wire);
  builder.Add(wire, edge(gp_Pnt2d(u0, 0), gp_Pnt2d(0, 0), a, b));
  builder.Add(wire, edge(gp_Pnt2d(0, 0), gp_Pnt2d(0, height), b, c));
  builder.Add(wire, edge(gp_Pnt2d(2 * pi, height), gp_Pnt2d(u0 + 2 * pi, 0), c, a));
  TopoDS_Face face;
  builder.MakeFace(face, cylinder, 1e-7);
  builder.Add(face, wire);
  const BrepTranslation t = shape_to_scene(face, "triangle");
  ASSERT_EQ(t.face_count, 1);
  for (const auto& f : t.fallbacks) ADD_FAILURE() << "fell back to a mesh: " << f.reason;
  ASSERT_TRUE(std::holds_alternative<TrimmedSurface>(t.scene.root.shapes[0].geometry));
  const auto& s = std::get<TrimmedSurface>(t.scene.root.shapes[0].geometry);
  EXPECT_NO_THROW(validate(s, "triangle"));
  EXPECT_TRUE(region_left_of_loop(s, 0));
  const double area = measure_trimmed_surface(s, Eigen::Affine3d::Identity()).area;
  EXPECT_NEAR(area, 0.5 * r * -u0 * height, close * area);
  TessellationReport report;
  const double deviation = 1e-3;
  const TriangleMesh mesh = tessellate_to_deviation(s, deviation, &report);
  EXPECT_EQ(report.uncertified_triangles, 0);
  EXPECT_LE(measure_deviation(mesh, s).overall.max, deviation);
}

TEST(FaceConversion, BrokenFaceBecomesAReportedMesh) {
  // A square whose last edge's pcurve ends 1 mm away from where the first starts: the wire is open.
  Handle(Geom_Plane) plane = new Geom_Plane(gp_Ax3());
  BRep_Builder builder;
  TopoDS_Face face;
  builder.MakeFace(face, plane, 1e-7);
  const std::array<gp_Pnt2d, 5> corners = {gp_Pnt2d(0, 0), gp_Pnt2d(10, 0), gp_Pnt2d(10, 10), gp_Pnt2d(0, 10), gp_Pnt2d(0, 1)};
  TopoDS_Wire wire;
  builder.MakeWire(wire);
  for (int i = 0; i < 4; ++i) {
    const gp_Vec2d d(corners[i], corners[i + 1]);
    BRepBuilderAPI_MakeEdge edge(new Geom2d_Line(corners[i], gp_Dir2d(d)), plane, 0.0, d.Magnitude());
    builder.Add(wire, edge.Edge());
  }
  builder.Add(face, wire);
  BRepLib::BuildCurves3d(face);
  const BrepTranslation t = shape_to_scene(face, "broken");
  ASSERT_EQ(t.face_count, 1);
  ASSERT_EQ(t.fallbacks.size(), 1u);
  EXPECT_EQ(t.fallbacks[0].face_index, 1);
  EXPECT_EQ(t.fallbacks[0].surface_type, "Plane");
  EXPECT_EQ(t.fallbacks[0].node, "broken");
  EXPECT_FALSE(t.fallbacks[0].reason.empty());
  EXPECT_EQ(t.fallbacks[0].reason.find('\n'), std::string::npos);
  ASSERT_EQ(t.scene.root.shapes.size(), 1u);
  EXPECT_EQ(t.scene.root.shapes[0].source_entity, "face 1 (mesh)");
  EXPECT_TRUE(std::holds_alternative<TriangleMesh>(t.scene.root.shapes[0].geometry));
  std::printf("fallback reason: %s\n", t.fallbacks[0].reason.c_str());
}

}  // namespace
}  // namespace cadnurbs::test
