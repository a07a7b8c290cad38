// Breps and Extrusions of .3dm files written by Rhino and openNURBS's examples, read into trimmed NURBS
// faces with the Brep's edge identity.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <string>
#include <variant>
#include <vector>

#include "core/nurbs_surface.hpp"
#include "core/point_in_loops.hpp"
#include "core/triangle_mesh.hpp"
#include "core/trimmed_surface.hpp"
#include "formats/3dm/brep_object.hpp"
#include "formats/3dm/rhino_file.hpp"

namespace cadnurbs::rhino {
namespace {

std::string corpus(const std::string& name) { return std::string(CADNURBS_SHARED_DIR) + "/corpus/3dm/" + name; }

std::vector<RhinoGeometry> objects_of(const std::string& name) {
  std::vector<RhinoGeometry> out;
  for (auto& record : read_3dm_file(corpus(name)).objects) out.push_back(std::move(record.geometry));
  return out;
}

std::vector<RhinoBrep> breps_of(const std::string& name) {
  std::vector<RhinoBrep> out;
  for (auto& g : objects_of(name))
    if (auto* b = std::get_if<RhinoBrep>(&g)) out.push_back(std::move(*b));
  return out;
}

Eigen::Vector3d at(const TrimmedSurface& face, const Eigen::Vector2d& uv) {
  return surface_point(face.surface, uv.x(), uv.y());
}

// One use of a Brep edge by a trim: the 3D points where the trim starts and ends, in the edge's direction.
struct EdgeUse {
  int face = 0;
  bool reversed = false;
  Eigen::Vector3d start, end;
};

std::map<int, std::vector<EdgeUse>> edge_uses(const RhinoBrep& brep) {
  std::map<int, std::vector<EdgeUse>> uses;
  for (std::size_t f = 0; f < brep.faces.size(); ++f)
    for (const auto& loop : brep.faces[f].loops)
      for (std::size_t s = 0; s < loop.segments.size(); ++s) {
        const TrimEdgeRef ref = loop.edges.at(s);
        if (ref.edge < 0) continue;
        EdgeUse use{static_cast<int>(f), ref.reversed, at(brep.faces[f], segment_start(loop.segments[s])),
                    at(brep.faces[f], segment_end(loop.segments[s]))};
        if (ref.reversed) std::swap(use.start, use.end);
        uses[ref.edge].push_back(use);
      }
  return uses;
}

// Area of a surface over a rectangle of its domain, by 24 x 24 Gauss-Legendre points per knot span
// (exact to round-off for the bilinear patches here, whose |Su x Sv| is smooth).
double area_over(const NurbsSurface& s, Eigen::Vector2d lo, Eigen::Vector2d hi) {
  // Nodes and weights on [-1, 1] by Newton's method on the Legendre polynomial.
  constexpr int n = 24;
  std::array<double, n> x{}, w{};
  for (int i = 0; i < n; ++i) {
    double z = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1) * z * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1);
      const double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    x[i] = z;
    w[i] = 2 / ((1 - z * z) * dp * dp);
  }
  double area = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = lo.x() + (hi.x() - lo.x()) * (x[i] + 1) / 2, v = lo.y() + (hi.y() - lo.y()) * (x[j] + 1) / 2;
      const auto d = surface_derivatives(s, u, v, 1);
      area += w[i] * w[j] * d[1][0].cross(d[0][1]).norm();
    }
  return area * (hi.x() - lo.x()) * (hi.y() - lo.y()) / 4;
}

// The bilinear patch through four corners (SW, SE, NE, NW), its area the same way: the reference.
double bilinear_area(const std::array<Eigen::Vector3d, 4>& c) {
  NurbsSurface s;
  s.u_count = s.v_count = 2;
  s.u_knots = s.v_knots = {0, 0, 1, 1};
  s.points = {c[0], c[1], c[3], c[2]};
  return area_over(s, {0, 0}, {1, 1});
}

// openNURBS's example_brep.cpp, which wrote v7_my_brep.3dm: the twisted cube's corners A..H and its six
// faces as corner quadruples.
const std::array<Eigen::Vector3d, 8> kCorners = {
    Eigen::Vector3d(0, 0, 0),  Eigen::Vector3d(10, 0, 0), Eigen::Vector3d(10, 8, -1), Eigen::Vector3d(0, 6, 0),
    Eigen::Vector3d(1, 2, 11), Eigen::Vector3d(10, 0, 12), Eigen::Vector3d(10, 7, 13), Eigen::Vector3d(0, 6, 12)};
const std::array<std::array<int, 4>, 6> kFaces = {{{0, 1, 2, 3}, {1, 2, 6, 5}, {2, 3, 7, 6}, {0, 3, 7, 4}, {0, 1, 5, 4}, {4, 5, 6, 7}}};

TEST(BrepObject, TwistedCubeHasSixFacesTwelveEdgesEachUsedTwiceOppositely) {
  const auto breps = breps_of("v7_my_brep.3dm");
  ASSERT_EQ(breps.size(), 1u);
  const RhinoBrep& brep = breps[0];
  EXPECT_TRUE(brep.skipped_faces.empty()) << brep.skipped_faces.front();
  ASSERT_EQ(brep.faces.size(), 6u);
  EXPECT_EQ(brep.edge_count, 12);
  const auto uses = edge_uses(brep);
  EXPECT_EQ(uses.size(), 12u);
  for (const auto& [edge, list] : uses) {
    ASSERT_EQ(list.size(), 2u) << "edge " << edge;
    EXPECT_NE(list[0].reversed, list[1].reversed) << "edge " << edge;
    EXPECT_NE(list[0].face, list[1].face) << "edge " << edge;
    // Both faces put the edge at the same place, in the edge's direction.
    EXPECT_LT((list[0].start - list[1].start).norm(), 1e-12) << "edge " << edge;
    EXPECT_LT((list[0].end - list[1].end).norm(), 1e-12) << "edge " << edge;
  }
}

// The example's cube is oriented inwards: face ABCD (m_bRev false) has Su x Sv = (B - A) x (D - A) = +z
// at the bottom, and the five faces with m_bRev set agree with it. What is asserted is that all six faces
// agree, which they do only when m_bRev is honoured.
TEST(BrepObject, TwistedCubeFacesHaveTheBilinearPatchAreaAndAgreeingNormals) {
  const auto breps = breps_of("v7_my_brep.3dm");
  ASSERT_EQ(breps.size(), 1u);
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& c : kCorners) centre += c / 8;
  std::vector<bool> matched(kFaces.size(), false);
  for (const auto& face : breps[0].faces) {
    ASSERT_EQ(face.loops.size(), 1u);
    const TrimLoop& loop = face.loops[0];
    EXPECT_LT(loop_closure_gap(loop), 1e-12);
    EXPECT_GT(loop_signed_area(loop), 0);  // outer loop counter-clockwise
    // Which of the cube's faces: the one whose corners are the surface's control points.
    int which = -1;
    for (std::size_t k = 0; k < kFaces.size(); ++k) {
      int found = 0;
      for (int c : kFaces[k])
        for (const auto& p : face.surface.points) found += (p - kCorners[c]).norm() == 0 ? 1 : 0;
      if (found == 4) which = static_cast<int>(k);
    }
    ASSERT_GE(which, 0);
    matched[which] = true;
    // The loop covers the whole domain here, so the trimmed area is the surface's area over its domain.
    const auto poly = loop_polygon(loop);
    Eigen::Vector2d lo = poly[0], hi = poly[0];
    for (const auto& p : poly) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    EXPECT_NEAR(loop_signed_area(loop), (hi - lo).prod(), 1e-12);
    std::array<Eigen::Vector3d, 4> quad;
    for (int c = 0; c < 4; ++c) quad[c] = kCorners[kFaces[which][c]];
    const double expected = bilinear_area(quad);
    EXPECT_NEAR(area_over(face.surface, lo, hi), expected, 1e-9 * expected) << "face " << which;
    // The normal at the middle points towards the cube's centre.
    const Eigen::Vector2d mid = (lo + hi) / 2;
    const Eigen::Vector3d n = surface_normal(face.surface, mid.x(), mid.y());
    EXPECT_LT(n.dot(at(face, mid) - centre), 0) << "face " << which;
  }
  for (bool m : matched) EXPECT_TRUE(m);
}

TEST(BrepObject, TrimmedSurfaceLoopClosesCounterClockwise) {
  const auto breps = breps_of("v2_my_trimmed_surface.3dm");
  ASSERT_EQ(breps.size(), 1u);
  const RhinoBrep& brep = breps[0];
  EXPECT_TRUE(brep.skipped_faces.empty());
  ASSERT_EQ(brep.faces.size(), 1u);
  const TrimmedSurface& face = brep.faces[0];
  ASSERT_EQ(face.loops.size(), 1u);
  const TrimLoop& loop = face.loops[0];
  // example_write.cpp's write_trimmed_surface_example: a triangle A(1, 2), B(9, 1.5), C(7, 8) in the
  // plane's parameters, trims A->B, B->C, C->A, each on its own edge; area |AB x AC| / 2 = 25.5.
  ASSERT_EQ(loop.segments.size(), 3u);
  const std::array<Eigen::Vector2d, 3> corners = {Eigen::Vector2d(1, 2), Eigen::Vector2d(9, 1.5), Eigen::Vector2d(7, 8)};
  for (int i = 0; i < 3; ++i) {
    EXPECT_LT((segment_start(loop.segments[i]) - corners[i]).norm(), 1e-12) << "trim " << i;
    EXPECT_EQ(loop.edges.at(i), (TrimEdgeRef{i, false})) << "trim " << i;
  }
  EXPECT_EQ(brep.edge_count, 3);
  EXPECT_LT(loop_closure_gap(loop), 1e-12);
  EXPECT_NEAR(loop_signed_area(loop), 25.5, 1e-9);
  for (const auto& ref : loop.edges) EXPECT_LT(ref.edge, brep.edge_count);
  // The loop stays in the surface's domain.
  for (const auto& p : loop_polygon(loop)) {
    EXPECT_GE(p.x(), face.surface.u_start() - 1e-9);
    EXPECT_LE(p.x(), face.surface.u_end() + 1e-9);
    EXPECT_GE(p.y(), face.surface.v_start() - 1e-9);
    EXPECT_LE(p.y(), face.surface.v_end() + 1e-9);
  }
}

TEST(BrepObject, TeapotBrepsReadWithEveryFaceAndMatchingEdges) {
  const auto breps = breps_of("v5_teapot.3dm");
  ASSERT_EQ(breps.size(), 3u);
  EXPECT_EQ(breps[0].faces.size(), 19u);  // as read (lid, body, spout and handle Breps)
  EXPECT_EQ(breps[1].faces.size(), 10u);
  EXPECT_EQ(breps[2].faces.size(), 68u);
  std::size_t faces = 0;
  double worst_gap = 0;
  for (const auto& brep : breps) {
    EXPECT_TRUE(brep.skipped_faces.empty()) << brep.skipped_faces.front();
    faces += brep.faces.size();
    for (const auto& face : brep.faces)
      for (const auto& loop : face.loops) EXPECT_LT(loop_closure_gap(loop), 1e-9);
    // Two faces meeting at an edge put its ends at the same 3D points within twice the edge's tolerance
    // (each trim's image is within it of the edge). The revolution faces' trims, written in the angle
    // parameter, land 0.36 apart when not moved to the NURBS form's parameter.
    const auto uses = edge_uses(brep);
    EXPECT_EQ(uses.size(), static_cast<std::size_t>(brep.edge_count));
    for (const auto& [edge, list] : uses)
      for (std::size_t i = 1; i < list.size(); ++i) {
        const double gap = std::max((list[i].start - list[0].start).norm(), (list[i].end - list[0].end).norm());
        EXPECT_LE(gap, 2 * brep.edge_tolerances.at(edge) + 1e-9) << "edge " << edge;
        worst_gap = std::max(worst_gap, gap);
        EXPECT_NE(list[i].reversed, list[0].reversed) << "edge " << edge;
      }
  }
  // One face per surface the file holds (89 NURBS, 2 plane and 6 revolution surfaces in the three Breps).
  EXPECT_EQ(faces, 97u);
  EXPECT_GT(worst_gap, 0);  // the file's edges are not exact: the check above is not vacuous
}

// The integral of integrand(S, Su, Sv) over a face's trimmed region: midpoint rule on an n x n grid of
// its domain, cells kept by the even-odd test at their centres.
template <typename Integrand>
double integrate(const TrimmedSurface& face, int n, Integrand integrand) {
  std::vector<std::vector<Eigen::Vector2d>> polygons;
  for (const auto& loop : face.loops) polygons.push_back(loop_polygon(loop));
  const PointInLoops region(polygons);
  const NurbsSurface& s = face.surface;
  const double du = (s.u_end() - s.u_start()) / n, dv = (s.v_end() - s.v_start()) / n;
  double sum = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = s.u_start() + (i + 0.5) * du, v = s.v_start() + (j + 0.5) * dv;
      if (!region.inside({u, v})) continue;
      const auto d = surface_derivatives(s, u, v, 1);
      sum += integrand(d[0][0], d[1][0], d[0][1]) * du * dv;
    }
  return sum;
}

double trimmed_area(const TrimmedSurface& face, int n) {
  return integrate(face, n, [](const auto&, const auto& su, const auto& sv) { return su.cross(sv).norm(); });
}

// Volume enclosed by the faces, (1/3) * sum over the faces of the integral of S . (Su x Sv): positive when
// the normals point out of a closed solid.
double signed_volume(const RhinoBrep& brep, int n) {
  double volume = 0;
  for (const auto& face : brep.faces)
    volume += integrate(face, n, [](const auto& p, const auto& su, const auto& sv) { return p.dot(su.cross(sv)) / 3; });
  return volume;
}

// v4_MechPartA.3dm: one legacy TL_Brep (Rhino 4) with the render mesh Rhino made for each face. The
// trimmed faces cover what Rhino meshed: total trimmed area within 1 % of the meshes' area (measured:
// 0.14 % at 300 x 300 samples).
TEST(BrepObject, LegacyBrepAreaAgreesWithRhinosRenderMeshes) {
  const auto breps = breps_of("v4_MechPartA.3dm");
  ASSERT_EQ(breps.size(), 1u);
  const RhinoBrep& brep = breps[0];
  EXPECT_TRUE(brep.skipped_faces.empty());
  ASSERT_EQ(brep.faces.size(), 41u);
  ASSERT_EQ(brep.render_meshes.size(), 41u);  // the file's 41 ON_Mesh objects, one per face
  double faces_area = 0, meshes_area = 0;
  for (std::size_t f = 0; f < brep.faces.size(); ++f) {
    ASSERT_TRUE(brep.render_meshes[f].has_value()) << "face " << f;
    const double a = trimmed_area(brep.faces[f], 200), m = mesh_area(*brep.render_meshes[f]);
    faces_area += a;
    meshes_area += m;
    // Per face the mesh's chords and our sampled boundary differ by up to 2.5 % (measured: a small
    // fillet); a face trimmed wrongly (a loop lost, or the complement kept) is off by far more.
    EXPECT_NEAR(a, m, 0.03 * m) << "face " << f;
  }
  EXPECT_NEAR(faces_area, meshes_area, 0.01 * meshes_area);
}

// v5_extrusions.3dm holds 7 Extrusions and the 10 curves they were made from. Each side face must start
// or end on one of those curves (the profile where the user drew it), run along one direction (the
// path) with every point at its profile point's distance from the path, and, with caps, close up: every
// edge used by two trims, oppositely, at the same 3D points.
TEST(ExtrusionObject, SidesSweepTheFileCurvesAndCapsCloseThem) {
  const auto objects = objects_of("v5_extrusions.3dm");
  std::vector<std::vector<Eigen::Vector3d>> curves;  // each file curve, densely sampled
  std::vector<RhinoBrep> extrusions;
  for (const auto& g : objects) {
    if (const auto* c = std::get_if<NurbsCurve>(&g)) {
      std::vector<Eigen::Vector3d> points;
      for (int k = 0; k <= 4000; ++k)
        points.push_back(curve_point(*c, c->domain_start() + (c->domain_end() - c->domain_start()) * k / 4000));
      curves.push_back(std::move(points));
    } else if (const auto* b = std::get_if<RhinoBrep>(&g)) {
      extrusions.push_back(*b);
    }
  }
  ASSERT_EQ(curves.size(), 10u);
  ASSERT_EQ(extrusions.size(), 7u);
  // Faces: one side per profile, plus two caps on the closed ones (2 profiles: an outer and a hole).
  const std::vector<std::size_t> face_counts = {4, 4, 3, 3, 1, 1, 4};
  auto distance_to_curves = [&](const Eigen::Vector3d& p) {
    double best = 1e300;
    for (const auto& c : curves)
      for (const auto& q : c) best = std::min(best, (p - q).squaredNorm());
    return std::sqrt(best);
  };
  for (std::size_t e = 0; e < extrusions.size(); ++e) {
    const RhinoBrep& x = extrusions[e];
    EXPECT_TRUE(x.skipped_faces.empty());
    ASSERT_EQ(x.faces.size(), face_counts[e]) << "extrusion " << e;
    // Side faces are the ones bounded by four straight trims.
    for (const auto& face : x.faces) {
      if (face.loops.size() != 1 || face.loops[0].segments.size() != 4) continue;
      const NurbsSurface& s = face.surface;
      // Which parameter runs along the path: the one whose iso lines are straight.
      const bool path_is_v = s.v_order == 2 && s.v_count == 2;
      auto point = [&](double along_profile, double along_path) {
        const double u = path_is_v ? along_profile : along_path, v = path_is_v ? along_path : along_profile;
        return surface_point(s, s.u_start() + (s.u_end() - s.u_start()) * u, s.v_start() + (s.v_end() - s.v_start()) * v);
      };
      double on_curve[2] = {0, 0};
      Eigen::Vector3d direction = (point(0, 1) - point(0, 0)).normalized();
      for (int k = 0; k <= 40; ++k) {
        const double t = k / 40.0;
        for (int end = 0; end < 2; ++end) on_curve[end] = std::max(on_curve[end], distance_to_curves(point(t, end)));
        const Eigen::Vector3d a = point(t, 0), b = point(t, 1);
        EXPECT_LT((b - a).normalized().cross(direction).norm(), 1e-9) << "extrusion " << e;
        // Midway along the path: on the straight line between the ends (same distance from the path).
        EXPECT_LT((point(t, 0.5) - (a + b) / 2).norm(), 1e-9 * (b - a).norm()) << "extrusion " << e;
      }
      // The sampled curves are 1/4000 of their length apart: a point on a curve is within that of a sample.
      EXPECT_LT(std::min(on_curve[0], on_curve[1]), 0.02) << "extrusion " << e;
      EXPECT_GT(std::max(on_curve[0], on_curve[1]), 1.0) << "extrusion " << e;  // the other end is elsewhere
    }
    const auto uses = edge_uses(x);
    EXPECT_EQ(uses.size(), static_cast<std::size_t>(x.edge_count));
    for (const auto& [edge, list] : uses) {
      if (x.faces.size() == 1) continue;  // an open extrusion's bottom and top edges bound one face
      ASSERT_EQ(list.size(), 2u) << "extrusion " << e << " edge " << edge;
      EXPECT_NE(list[0].reversed, list[1].reversed);
      EXPECT_LT((list[0].start - list[1].start).norm(), 1e-9);
      EXPECT_LT((list[0].end - list[1].end).norm(), 1e-9);
    }
    for (const auto& face : x.faces)
      for (const auto& loop : face.loops) EXPECT_LT(loop_closure_gap(loop), 1e-12);
    // A capped extrusion is a solid with its normals pointing out.
    if (x.faces.size() > 1) {
      EXPECT_GT(signed_volume(x, 200), 0) << "extrusion " << e;
    }
  }
}

}  // namespace
}  // namespace cadnurbs::rhino
