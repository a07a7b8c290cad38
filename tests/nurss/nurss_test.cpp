// Quadratic NURSS (analysis/nurss): refinement against NURBS knot insertion and against Doo-Sabin's
// weights, the limit mesh against the NURBS it came from, closed meshes with n-gon faces, and the
// capping as one NURSS with its handrail connections as n-gons.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "analysis/mesh/count_boundary_edges.hpp"
#include "analysis/measure/measure_deviation.hpp"
#include "analysis/nurss/nurss_face_point.hpp"
#include "analysis/nurss/nurss_from_nurbs.hpp"
#include "analysis/nurss/nurss_limit_mesh.hpp"
#include "analysis/nurss/nurss_storage.hpp"
#include "analysis/nurss/refine_nurss.hpp"
#include "analysis/mesh/weld_exact.hpp"
#include "core/geometry_error.hpp"
#include "core/knot_insertion.hpp"
#include "formats/vrml/vrml_reader.hpp"
#include "formats/vrml/vrml_writer.hpp"
#include "samples/capping_shapes.hpp"

namespace cadnurbs {
namespace {

// A wavy quadratic net over [0, 10] x [0, 8] with the given knots (clamped or not), rational if asked.
NurbsSurface wavy_net(const std::vector<double>& u_knots, const std::vector<double>& v_knots, bool rational) {
  NurbsSurface s;
  s.u_order = s.v_order = 3;
  s.u_knots = u_knots;
  s.v_knots = v_knots;
  s.u_count = static_cast<int>(u_knots.size()) - 3;
  s.v_count = static_cast<int>(v_knots.size()) - 3;
  for (int j = 0; j < s.v_count; ++j)
    for (int i = 0; i < s.u_count; ++i) {
      s.points.emplace_back(10.0 * i / (s.u_count - 1) + 0.3 * std::sin(j), 8.0 * j / (s.v_count - 1),
                            2 * std::sin(1.3 * i) * std::cos(0.7 * j));
      if (rational) s.weights.push_back(1 + 0.5 * std::sin(1.7 * i + 2.3 * j) * std::sin(1.7 * i + 2.3 * j));
    }
  return s;
}

// Midpoints of the non-empty knot spans of the domain.
std::vector<double> span_midpoints(const std::vector<double>& knots) {
  std::vector<double> mid;
  for (size_t i = 2; i + 3 < knots.size(); ++i)
    if (knots[i + 1] > knots[i]) mid.push_back((knots[i] + knots[i + 1]) / 2);
  return mid;
}

// Largest distance between the refined NURSS net and the NURBS net refined at every span midpoint, in
// homogeneous coordinates. New vertex of (quad (i, j), corner k) is 4 (i + j (m-1)) + k; corners
// (i,j), (i+1,j), (i+1,j+1), (i,j+1) land at (2i, 2j), (2i+1, 2j), (2i+1, 2j+1), (2i, 2j+1).
double refinement_vs_knot_insertion(const NurbsSurface& surface) {
  const NurssMesh refined = refine_nurss(nurss_from_nurbs({surface}));
  NurbsSurface inserted = refine_knots(surface, SurfaceDirection::u, span_midpoints(surface.u_knots));
  inserted = refine_knots(inserted, SurfaceDirection::v, span_midpoints(surface.v_knots));
  EXPECT_EQ(inserted.u_count, 2 * surface.u_count - 2);
  EXPECT_EQ(inserted.v_count, 2 * surface.v_count - 2);
  EXPECT_EQ(refined.vertex_count(), inserted.u_count * inserted.v_count);
  const int at[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  double worst = 0;
  for (int j = 0; j + 1 < surface.v_count; ++j)
    for (int i = 0; i + 1 < surface.u_count; ++i)
      for (int k = 0; k < 4; ++k) {
        const NurssVertexId v(4 * (i + j * (surface.u_count - 1)) + k);
        const int I = 2 * i + at[k][0], J = 2 * j + at[k][1];
        const double w = inserted.weight(I, J);
        const Eigen::Vector4d expected(w * inserted.point(I, J).x(), w * inserted.point(I, J).y(),
                                       w * inserted.point(I, J).z(), w);
        worst = std::max(worst, (refined.homogeneous(v) - expected).norm());
      }
  return worst;
}

const std::vector<double> kUKnots = {0, 0, 0, 1, 2.5, 3, 4.5, 7, 7, 7};  // 7 points, non-uniform
const std::vector<double> kVKnots = {0, 0, 0, 0.5, 2, 2.25, 4, 4, 4};    // 6 points

TEST(NurssRefinement, EqualsKnotInsertionAtIntervalMidpoints) {
  const double polynomial = refinement_vs_knot_insertion(wavy_net(kUKnots, kVKnots, false));
  const double rational = refinement_vs_knot_insertion(wavy_net(kUKnots, kVKnots, true));
  std::printf("[ figures ] refinement vs knot insertion: %.3g (polynomial), %.3g (rational, homogeneous)\n",
              polynomial, rational);
  EXPECT_LE(polynomial, 1e-12);
  EXPECT_LE(rational, 1e-12);
}

TEST(NurssRefinement, NewIntervalsAreHalved) {
  const NurbsSurface s = wavy_net(kUKnots, kVKnots, false);
  const NurssMesh refined = refine_nurss(nurss_from_nurbs({s}));
  // Quad (1, 2), corner 0 sits at P_{1,2}: it holds d_1/2 = (t_3 - t_2)/2 = (1 - 0)/2 on its u edges and
  // e_2/2 = (2 - 0.5)/2 on its v edges; corner 1, at P_{2,2}, holds d_2/2 = (2.5 - 1)/2 toward corner 0.
  const int f = 1 + 2 * (s.u_count - 1);
  const NurssVertexId me(4 * f), along_u(4 * f + 1), along_v(4 * f + 3);
  EXPECT_DOUBLE_EQ(refined.interval(me, along_u), 0.5);
  EXPECT_DOUBLE_EQ(refined.interval(me, along_v), 0.75);
  EXPECT_DOUBLE_EQ(refined.interval(along_u, me), 0.75);
  // The V-edge across the old side P_{1,2} P_{2,2} (to quad (1, 1)'s corner at P_{1,2}) runs along v.
  const NurssVertexId below(4 * (1 + 1 * (s.u_count - 1)) + 3);
  EXPECT_DOUBLE_EQ(refined.interval(me, below), 0.75);
}

TEST(NurssFacePoint, IsTheSurfacePointAtTheFacesKnots) {
  // Double knots (a C0 joint of arcs) included; rational.
  const NurbsSurface s = wavy_net({0, 0, 0, 1, 1, 3, 4.5, 7, 7, 7}, kVKnots, true);
  const NurssMesh mesh = nurss_from_nurbs({s});
  double worst = 0;
  for (int j = 0; j + 1 < s.v_count; ++j)
    for (int i = 0; i + 1 < s.u_count; ++i) {
      const Eigen::Vector3d p = euclidean(nurss_face_point(mesh, NurssFaceId(i + j * (s.u_count - 1))));
      worst = std::max(worst, (p - surface_point(s, s.u_knots[i + 2], s.v_knots[j + 2])).norm());
    }
  EXPECT_LE(worst, 1e-12);
}

TEST(NurssRefinement, UniformIntervalsGiveDooSabinWeights) {
  for (int n : {3, 5, 6, 8}) {
    NurssMesh mesh;
    std::vector<NurssVertexId> corners;
    std::vector<Eigen::Vector3d> p;
    for (int k = 0; k < n; ++k) {
      const double a = 2 * std::numbers::pi * k / n;
      p.emplace_back(std::cos(a) * (1 + 0.3 * k), std::sin(a), 0.2 * k * k);
      corners.push_back(mesh.add_vertex(p.back()));
    }
    mesh.add_face(corners);
    for (int k = 0; k < n; ++k) {
      mesh.set_interval(corners[k], corners[(k + 1) % n], 2.5);
      mesh.set_interval(corners[(k + 1) % n], corners[k], 2.5);
    }
    const NurssMesh refined = refine_nurss(mesh);
    ASSERT_EQ(refined.vertex_count(), n);
    double worst = 0;
    for (int i = 0; i < n; ++i) {
      Eigen::Vector3d expected = Eigen::Vector3d::Zero();
      for (int j = 0; j < n; ++j) {
        const double alpha = i == j ? 0.25 + 5.0 / (4 * n) : (3 + 2 * std::cos(2 * std::numbers::pi * (i - j) / n)) / (4 * n);
        expected += alpha * p[j];
      }
      worst = std::max(worst, (refined.position(NurssVertexId(i)) - expected).norm());
    }
    EXPECT_LE(worst, 1e-13) << n << "-gon";
  }
}

TEST(NurssLimitMesh, SinglePatchLiesOnItsNurbs) {
  const NurbsSurface s = wavy_net(kUKnots, kVKnots, true);
  TrimmedSurface whole;
  whole.surface = s;
  const NurssMesh mesh = nurss_from_nurbs({s});
  double previous = 0;
  for (int levels : {2, 3, 4}) {
    const NurssTriangles limit = nurss_limit_mesh(mesh, levels);
    const DeviationMeasure d = measure_deviation(limit.mesh, whole);
    std::printf("[ figures ] single rational patch (10 x 8 x 4 units), level %d: %zu triangles, deviation %.3g "
                "(mesh->surface %.3g, surface->mesh %.3g)\n",
                levels, limit.mesh.triangles.size(), d.overall.max, d.mesh_to_surface.max, d.surface_to_mesh.max);
    if (levels == 4) {
      EXPECT_LE(d.overall.max, 5e-3);
    }
    if (previous > 0) {
      EXPECT_LE(d.overall.max, previous / 3) << "chord error must fall ~4x a level";
    }
    previous = d.overall.max;
  }
}

// A prism: a regular n-gon at the bottom, a wobbly one on top (so that no symmetry keeps the top's face
// point still), n quads between, every vertex of valence 3. Knot intervals: 1 round the bottom, 1 and 2
// (alternating, different at the two ends of an edge) round the top, 1.5 up the sides.
NurssMesh prism(int n) {
  NurssMesh mesh;
  std::vector<NurssVertexId> bottom, top;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * std::numbers::pi * k / n;
    bottom.push_back(mesh.add_vertex({std::cos(a), std::sin(a), 0}));
  }
  for (int k = 0; k < n; ++k) {
    const double a = 2 * std::numbers::pi * k / n, r = 1 + 0.3 * std::sin(3.0 * k);
    top.push_back(mesh.add_vertex({r * std::cos(a), r * std::sin(a), 1.5 + 0.4 * std::cos(2.0 * k)}));
  }
  mesh.add_face(top, 1);
  mesh.add_face(std::vector<NurssVertexId>(bottom.rbegin(), bottom.rend()), 1);
  for (int k = 0; k < n; ++k) mesh.add_face({bottom[k], bottom[(k + 1) % n], top[(k + 1) % n], top[k]});
  for (int k = 0; k < n; ++k) {
    const int l = (k + 1) % n;
    mesh.set_interval(bottom[k], bottom[l], 1);
    mesh.set_interval(bottom[l], bottom[k], 1);
    mesh.set_interval(top[k], top[l], 1 + k % 2);
    mesh.set_interval(top[l], top[k], 1);
    mesh.set_interval(bottom[k], top[k], 1.5);
    mesh.set_interval(top[k], bottom[k], 1.5);
  }
  return mesh;
}

double face_diameter(const NurssMesh& mesh, NurssFaceId f) {
  double d = 0;
  for (NurssVertexId a : mesh.corners(f))
    for (NurssVertexId b : mesh.corners(f)) d = std::max(d, (mesh.position(a) - mesh.position(b)).norm());
  return d;
}

TEST(NurssClosedMesh, NgonFacesSubdivideWatertightAndConverge) {
  for (int n : {4, 5, 7}) {  // 4: the cube's control mesh (its vertices of valence 3 become triangles)
    NurssMesh mesh = prism(n);
    double previous_diameter = face_diameter(mesh, NurssFaceId(0)), previous_move = 0;
    Eigen::Vector3d previous_point = euclidean(nurss_face_point(mesh, NurssFaceId(0)));
    for (int level = 1; level <= 5; ++level) {
      mesh = refine_nurss(mesh);
      // Face 0 stays the top n-gon's F-face at every level (refine_nurss's numbering).
      ASSERT_EQ(mesh.corners(NurssFaceId(0)).size(), static_cast<size_t>(n));
      const double diameter = face_diameter(mesh, NurssFaceId(0));
      const Eigen::Vector3d point = euclidean(nurss_face_point(mesh, NurssFaceId(0)));
      const double move = (point - previous_point).norm();
      EXPECT_LE(diameter, 0.75 * previous_diameter) << n << "-gon prism, level " << level;
      if (level > 1) {
        EXPECT_LE(move, 0.75 * previous_move + 1e-15) << n << "-gon prism, level " << level;
      }
      previous_diameter = diameter;
      previous_move = move;
      previous_point = point;
      for (const auto& t : {nurss_control_triangles(mesh).mesh, nurss_face_point_mesh(mesh).mesh}) {
        const EdgeCounts e = count_boundary_edges(weld_exact(t));
        EXPECT_EQ(e.boundary, 0) << n << "-gon prism, level " << level;
        EXPECT_EQ(e.non_manifold, 0) << n << "-gon prism, level " << level;
      }
    }
    std::printf("[ figures ] %d-gon prism after 5 levels: n-gon diameter %.3g (of 2), face point moved %.3g in the "
                "last level\n",
                n, previous_diameter, previous_move);
  }
}

TEST(NurssStorage, CountsTheCubesNet) {
  const NurssStorage s = nurss_storage(prism(4));
  EXPECT_EQ(s.control_points, 8);
  EXPECT_EQ(s.faces, 6);
  EXPECT_EQ(s.edges, 12);
  EXPECT_EQ(s.knot_intervals, 24);
  EXPECT_EQ(s.floats, 8 * 4 + 24);
  EXPECT_EQ(s.connectivity_integers, 6 * 5);
}

TEST(NurssMesh, RefusesWhatItCannotRefine) {
  NurbsSurface cubic = wavy_net(kUKnots, kVKnots, false);
  cubic.u_order = 4;
  cubic.u_count -= 1;
  cubic.points.resize(cubic.u_count * cubic.v_count);
  try {
    nurss_from_nurbs({cubic});
    ADD_FAILURE() << "an order-4 net was taken";
  } catch (const GeometryError& e) {
    EXPECT_STREQ(e.what(), "surface 0: is of order 4 x 3; a quadratic NURSS needs order 3 x 3");
  }
  NurssMesh mesh;
  const NurssVertexId a = mesh.add_vertex({0, 0, 0}), b = mesh.add_vertex({1, 0, 0}), c = mesh.add_vertex({0, 1, 0});
  EXPECT_THROW(mesh.add_face({a, b, a}), GeometryError);
  mesh.add_face({a, b, c});
  EXPECT_THROW(mesh.add_face({a, b, c}), GeometryError);  // the same sides again
  try {
    refine_nurss(mesh);
    ADD_FAILURE() << "a mesh without knot intervals was refined";
  } catch (const GeometryError& e) {
    EXPECT_STREQ(e.what(), "NURSS mesh: edge 0-1: vertex 0 holds no knot interval >= 0");
  }
}

const TrimmedSurface& shape_named(const Scene& scene, const std::string& name) {
  for (const auto& s : scene.root.shapes)
    if (s.name == name) return std::get<TrimmedSurface>(s.geometry);
  throw std::runtime_error("no shape " + name);
}

TEST(NurssCapping, LimitMeshLiesOnTheNurbsAwayFromTheNgons) {
  const Scene scene = capping_nurbs(bundled_capping("capping-90"));
  const TrimmedSurface& body = shape_named(scene, "body");
  // The profile is closed: its first and last control points coincide and weld into the seam.
  NurssMesh mesh = nurss_from_nurbs({body.surface}, 1e-6);
  const std::vector<NurssFaceId> lids = fill_boundary_loops(mesh, 1);
  ASSERT_EQ(lids.size(), 2u);
  EXPECT_EQ(mesh.vertex_count(), body.surface.u_count * body.surface.v_count - body.surface.v_count);
  EXPECT_EQ(mesh.corners(lids[0]).size(), static_cast<size_t>(body.surface.u_count - 1));
  const NurssStorage st = nurss_storage(mesh);
  std::printf("[ figures ] capping-90 NURSS: %ld control points, %ld faces (2 n-gons of %zu sides), %ld edges, "
              "%ld knot intervals, %ld floats (thesis: 4,728 for 591 points), %ld connectivity integers\n",
              st.control_points, st.faces, mesh.corners(lids[0]).size(), st.edges, st.knot_intervals, st.floats,
              st.connectivity_integers);
  EXPECT_EQ(st.floats, 4 * st.control_points + 2 * st.edges);

  Scene body_only;
  body_only.root.shapes.push_back({"body", body, std::nullopt});
  const int levels = 3;
  const NurssTriangles limit = nurss_limit_mesh(mesh, levels);
  const TriangleMesh away = nurss_triangles_with_label(limit, 0);  // from body faces only
  // Every vertex of the limit mesh away from the n-gons is a point of the exact sweep.
  const CappingDefinition capping = bundled_capping("capping-90");
  double off_sweep = 0;
  for (const auto& p : away.positions) off_sweep = std::max(off_sweep, distance_to_swept_surface(capping, p));
  EXPECT_LE(off_sweep, 1e-9);
  DeviationOptions options;
  options.spacing = 1.5;  // mm
  const DeviationMeasure on_body = measure_deviation(away, body_only, options);
  const DeviationMeasure whole = measure_deviation(limit.mesh, scene, options);
  std::printf("[ figures ] capping-90 NURSS limit mesh, %d levels: %zu triangles (%zu away from the n-gons); away "
              "from the n-gons mesh->body %.3g mm; whole mesh vs body + trimmed lids: mesh->NURBS %.3g mm, "
              "NURBS->mesh %.3g mm\n",
              levels, limit.mesh.triangles.size(), away.triangles.size(), on_body.mesh_to_surface.max,
              whole.mesh_to_surface.max, whole.surface_to_mesh.max);
  EXPECT_LE(on_body.mesh_to_surface.max, 1.0);
  EXPECT_LE(whole.overall.max, 1.0);  // the n-gons' planar region fills the trimmed lids too

  // The limit mesh goes out as an IndexedFaceSet and comes back with every triangle.
  Scene written;
  written.root.shapes.push_back({"nurss-limit", limit.mesh, std::nullopt});
  VrmlWriteOptions vrml;
  vrml.encoding = VrmlEncoding::vrml97;
  const std::string text = format_vrml(written, vrml);
  EXPECT_NE(text.find("IndexedFaceSet"), std::string::npos);
  const Scene read = parse_vrml(text, "nurss-limit.wrl");
  size_t triangles_read = 0;
  for_each_shape(read, [&](const Shape& shape, const Eigen::Affine3d&, const Colour&) {
    if (const auto* m = std::get_if<TriangleMesh>(&shape.geometry)) triangles_read += m->triangles.size();
  });
  EXPECT_EQ(triangles_read, limit.mesh.triangles.size());
  // Everything from the n-gons is flat, in the plane of the lid it replaces.
  double off_lid_planes = 0;
  for (size_t t = 0; t < limit.mesh.triangles.size(); ++t) {
    if (limit.triangle_labels[t] != 1) continue;
    for (int k : limit.mesh.triangles[t]) {
      double nearest = 1e300;
      for (const char* lid : {"lid-start", "lid-end"}) {
        const auto& q = shape_named(scene, lid).surface.points;
        const Eigen::Vector3d normal = (q[1] - q[0]).cross(q[2] - q[0]).normalized();
        nearest = std::min(nearest, std::abs(normal.dot(limit.mesh.positions[k] - q[0])));
      }
      off_lid_planes = std::max(off_lid_planes, nearest);
    }
  }
  EXPECT_LE(off_lid_planes, 1e-9);
  // One closed surface: the lids' n-gons and the body meet without a crack.
  const EdgeCounts edges = count_boundary_edges(weld_exact(limit.mesh));
  EXPECT_EQ(edges.boundary, 0);
  EXPECT_EQ(edges.non_manifold, 0);
}

}  // namespace
}  // namespace cadnurbs
