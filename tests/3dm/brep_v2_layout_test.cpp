// Rhino 2's Brep layout (ON_Brep chunk version 2.x) on class data built here byte by byte from the layout
// brep_v2_layout.hpp describes, read through read_brep (the version dispatch). No file of the shared corpus holds this
// layout (its v2_my_trimmed_surface.3dm was written by a later openNURBS: Brep chunk 3.2), so the checks are closed
// forms of the planar faces built: areas, normals, the shared edge's directions.
#include <gtest/gtest.h>

#include <cstdint>

#include "core/nurbs_surface.hpp"
#include "formats/3dm/brep_object.hpp"
#include "tests/3dm/class_chunks.hpp"

namespace cadnurbs::rhino {
namespace {

using testing::ClassData;
using testing::error_of;
using testing::object_chunk;

constexpr const char* kV2NurbsCurveId = "76A709D5-1550-11D4-8000-0010830122F0";
constexpr const char* kPrefix = "hand.3dm: chunk 0x00027FFA at offset 0: Brep (Rhino 2 layout): ";

// An ON_NurbsCurve object (chunk 1.0): the line a -> b over [0, 1], of `dimension` 2 or 3.
std::string line_object(const Eigen::Vector3d& a, const Eigen::Vector3d& b, int dimension) {
  ClassData c;
  c.put<std::uint8_t>(0x10).put<std::int32_t>(dimension).put<std::int32_t>(0).put<std::int32_t>(2).put<std::int32_t>(2);
  c.put<std::int32_t>(0).put<std::int32_t>(0).doubles({0, 0, 0, 0, 0, 0});
  c.put<std::int32_t>(2).doubles({0, 1});
  c.put<std::int32_t>(2);
  for (const auto& p : {a, b})
    for (int k = 0; k < dimension; ++k) c.put(p[k]);
  return object_chunk(kV2NurbsCurveId, c.body);
}

// ON_PolyCurve class data (chunk 1.0, no object wrapper) of one segment over `parameters`.
std::string poly_curve(const std::string& segment, std::initializer_list<double> parameters) {
  ClassData c;
  c.put<std::uint8_t>(0x10).put<std::int32_t>(1).put<std::int32_t>(0).put<std::int32_t>(0).doubles({0, 0, 0, 0, 0, 0});
  c.put(static_cast<std::int32_t>(parameters.size())).doubles(parameters);
  return c.body + segment;
}

std::string trim_curve(double u0, double v0, double u1, double v1) {
  return poly_curve(line_object({u0, v0, 0}, {u1, v1, 0}, 2), {0, 1});
}

// ON_NurbsSurface class data (chunk 1.0, no object wrapper): the bilinear patch over [0, u1] x [0, 1] with corners p00,
// p10, p01, p11 (CV(i, j) written with j fastest).
std::string bilinear(double u1, const Eigen::Vector3d& p00, const Eigen::Vector3d& p10, const Eigen::Vector3d& p01,
                     const Eigen::Vector3d& p11) {
  ClassData c;
  c.put<std::uint8_t>(0x10).put<std::int32_t>(3).put<std::int32_t>(0);
  c.put<std::int32_t>(2).put<std::int32_t>(2).put<std::int32_t>(2).put<std::int32_t>(2);
  c.put<std::int32_t>(0).put<std::int32_t>(0).doubles({0, 0, 0, 0, 0, 0});
  c.put<std::int32_t>(2).doubles({0, u1});
  c.put<std::int32_t>(2).doubles({0, 1});
  c.put<std::int32_t>(4);
  for (const auto& p : {p00, p01, p10, p11}) c.doubles({p.x(), p.y(), p.z()});
  return c.body;
}

struct TrimRecord {
  int edge = -1;
  bool owns_edge = false;
  bool against_edge = false;
  double tolerance_3d = 0, tolerance_2d = 0;
};
struct LoopRecord {
  int type = 0;
  std::vector<TrimRecord> trims;
};
struct FaceRecord {
  bool reversed = false;
  std::vector<LoopRecord> loops;
};

// The whole class data: version byte 2.0, the header counts as given, curves, surfaces, face records, and a render mesh
// flag 0 per face, framed as ClassData::chunk() does.
std::string v2_brep(std::initializer_list<std::int32_t> counts, const std::vector<std::string>& curves_2d,
                    const std::vector<std::string>& curves_3d, const std::vector<std::string>& surfaces,
                    const std::vector<FaceRecord>& faces) {
  ClassData c;
  c.put<std::uint8_t>(0x20);
  for (const std::int32_t n : counts) c.put(n);
  c.put<std::int32_t>(1).doubles({0, 0, 0, 1, 1, 1});
  for (const auto& s : curves_2d) c.body += s;
  for (const auto& s : curves_3d) c.body += s;
  for (const auto& s : surfaces) c.body += s;
  std::int32_t trim_index = 0, loop_index = 0, face_index = 0;
  for (const FaceRecord& f : faces) {
    c.put(face_index++).put<std::int32_t>(-1).put<std::int32_t>(f.reversed).put<std::int32_t>(0);
    c.doubles({0, 0, 0, 1, 1, 1}).put(static_cast<std::int32_t>(f.loops.size()));
    for (const LoopRecord& l : f.loops) {
      c.put(loop_index++)
          .put<std::int32_t>(l.type)
          .doubles({0, 0, 1, 1})
          .put(static_cast<std::int32_t>(l.trims.size()));
      for (const TrimRecord& t : l.trims) {
        c.put(trim_index++).put<std::int32_t>(-1).put<std::uint8_t>(t.owns_edge).put<std::int32_t>(t.edge);
        c.put<std::int32_t>(t.against_edge)
            .put<std::int32_t>(0)
            .put<std::int32_t>(1)
            .doubles({t.tolerance_3d, t.tolerance_2d});
      }
    }
  }
  for (std::size_t i = 0; i < faces.size(); ++i) c.put<std::uint8_t>(0);
  return c.chunk();
}

RhinoBrep read(const std::string& bytes) {
  ArchiveReader reader(bytes, "hand.3dm", 70);
  reader.begin_chunk();
  return read_brep(reader);
}

std::string edge_3d(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return poly_curve(line_object(a, b, 3), {0, 1});
}

TrimRecord owner(int edge) { return {edge, true, false, 0, 0}; }

// Face 1: (u, v) in [0, 2] x [0, 1] -> (3u, 2v, 0), its outer loop the domain's sides written clockwise, a triangular
// hole written counter-clockwise. Face 2: (u, v) in [0, 1]^2 -> (6u, 0, -v), reversed, a triangle whose first side lies
// on face 1's side v = 0 (edge 3, shared). Face 3: its one 2D curve is a polycurve whose parameters do not increase.
std::string three_faces() {
  const std::vector<std::string> curves = {trim_curve(0, 0, 0, 1),
                                           trim_curve(0, 1, 2, 1),
                                           trim_curve(2, 1, 2, 0),
                                           trim_curve(2, 0, 0, 0),
                                           trim_curve(0.5, 0.25, 1.5, 0.25),
                                           trim_curve(1.5, 0.25, 1, 0.75),
                                           trim_curve(1, 0.75, 0.5, 0.25),
                                           trim_curve(0, 0, 1, 0),
                                           trim_curve(1, 0, 0, 1),
                                           trim_curve(0, 1, 0, 0),
                                           poly_curve(line_object({0, 0, 0}, {1, 0, 0}, 2), {1, 1})};
  std::vector<std::string> edges;
  for (int i = 0; i < 9; ++i)
    edges.push_back(i == 3 ? edge_3d({6, 0, 0}, {0, 0, 0}) : edge_3d({0, 0, 0}, {1, 0, 0}));  // stepped over
  const std::vector<std::string> surfaces = {bilinear(2, {0, 0, 0}, {6, 0, 0}, {0, 2, 0}, {6, 2, 0}),
                                             bilinear(1, {0, 0, 0}, {6, 0, 0}, {0, 0, -1}, {6, 0, -1}),
                                             bilinear(1, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0})};
  TrimRecord shared_on_1 = owner(3);
  shared_on_1.tolerance_3d = 0.001;
  const TrimRecord shared_on_2 = {3, false, true, 0.002, 0};
  const std::vector<FaceRecord> faces = {
      {false, {{0, {owner(0), owner(1), owner(2), shared_on_1}}, {1, {owner(4), owner(5), owner(6)}}}},
      {true, {{0, {shared_on_2, owner(7), owner(8)}}}},
      {false, {{0, {TrimRecord{}}}}}};
  return v2_brep({3, 9, 4, 11}, curves, edges, surfaces, faces);
}

Eigen::Vector3d point_at_start(const TrimmedSurface& face, const TrimSegment& segment) {
  const Eigen::Vector2d uv = segment_start(segment);
  return surface_point(face.surface, uv.x(), uv.y());
}

TEST(BrepV2Layout, FacesAreTheTrimmedPlanesWrittenWithTheirAreasNormalsAndSharedEdge) {
  const RhinoBrep brep = read(three_faces());
  EXPECT_EQ(brep.edge_count, 9);
  ASSERT_EQ(brep.edge_tolerances.size(), 9u);
  EXPECT_EQ(brep.edge_tolerances[3],
            0.002);  // the larger 3D tolerance of the edge's two trims
  EXPECT_EQ(brep.edge_tolerances[0], 0.0);
  EXPECT_TRUE(brep.render_meshes.empty());
  ASSERT_EQ(brep.faces.size(), 2u);
  EXPECT_EQ(brep.face_indices, (std::vector<int>{0, 1}));

  // Face 1: the loops turned to the VRML/X3D rule; area = (2 - 1/4) in (u, v) times the Jacobian 3 * 2.
  const TrimmedSurface& f1 = brep.faces[0];
  ASSERT_EQ(f1.loops.size(), 2u);
  EXPECT_NEAR(loop_signed_area(f1.loops[0]), 2.0, 1e-12);
  EXPECT_NEAR(loop_signed_area(f1.loops[1]), -0.25, 1e-12);
  const auto d1 = surface_derivatives(f1.surface, 0.3, 0.4, 1);
  EXPECT_NEAR((loop_signed_area(f1.loops[0]) + loop_signed_area(f1.loops[1])) * d1[1][0].cross(d1[0][1]).norm(), 10.5,
              1e-12);
  EXPECT_NEAR(surface_normal(f1.surface, 0.3, 0.4).z(), 1.0, 1e-12);

  // Face 2, reversed: normal -y (the surface's own is +y), triangle area 1/2
  // * 6.
  const TrimmedSurface& f2 = brep.faces[1];
  ASSERT_EQ(f2.loops.size(), 1u);
  const auto d2 = surface_derivatives(f2.surface, 0.2, 0.2, 1);
  EXPECT_NEAR(std::abs(loop_signed_area(f2.loops[0])) * d2[1][0].cross(d2[0][1]).norm(), 3.0, 1e-12);
  EXPECT_GT(loop_signed_area(f2.loops[0]), 0);
  EXPECT_NEAR(surface_normal(f2.surface, 0.2, 0.2).y(), -1.0, 1e-12);

  // Edge 3 runs (6, 0, 0) -> (0, 0, 0), as its owning trim on face 1 was written. It is used once by each face, in
  // opposite directions in space (a consistently oriented pair), and the references say so.
  auto use_of_edge_3 = [](const TrimmedSurface& f) {
    for (const auto& loop : f.loops)
      for (std::size_t i = 0; i < loop.edges.size(); ++i)
        if (loop.edges[i].edge == 3) return std::pair{&loop.segments[i], loop.edges[i].reversed};
    return std::pair<const TrimSegment*, bool>{nullptr, false};
  };
  const auto [s1, reversed1] = use_of_edge_3(f1);
  const auto [s2, reversed2] = use_of_edge_3(f2);
  ASSERT_NE(s1, nullptr);
  ASSERT_NE(s2, nullptr);
  EXPECT_NE(reversed1, reversed2);
  const Eigen::Vector3d start1 = point_at_start(f1, *s1), start2 = point_at_start(f2, *s2);
  EXPECT_LT((start1 - Eigen::Vector3d(reversed1 ? 0 : 6, 0, 0)).norm(), 1e-12);
  EXPECT_LT((start2 - Eigen::Vector3d(reversed2 ? 0 : 6, 0, 0)).norm(), 1e-12);
  EXPECT_NEAR((start1 - start2).norm(), 6.0, 1e-12);

  // Face 3 is left out, saying which curve and why; the others are kept.
  ASSERT_EQ(brep.skipped_faces.size(), 1u);
  EXPECT_EQ(brep.skipped_face_indices, std::vector<int>{2});
  EXPECT_EQ(brep.skipped_faces[0],
            "face 3 loop 1: 2D curve 10: chunk 0x00027FFA at offset 0: "
            "ON_PolyCurve: segment parameter 1 (1) does not "
            "exceed the one before (1)");
}

TEST(BrepV2Layout, RefusesWhatOpenNurbsRefuses) {
  const std::vector<std::string> one_curve = {trim_curve(0, 0, 1, 0)};
  const std::vector<std::string> one_edge = {edge_3d({0, 0, 0}, {1, 0, 0})};
  const std::vector<std::string> one_surface = {bilinear(1, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0})};
  auto error = [](const std::string& bytes) { return error_of(bytes, [](ArchiveReader& r) { read_brep(r); }); };

  EXPECT_EQ(error(v2_brep({0, 1, 1, 1}, one_curve, one_edge, one_surface, {})),
            std::string(kPrefix) + "face count 0 is below 1");
  EXPECT_EQ(error(v2_brep({1, 1, 1, 1}, one_curve, one_edge, one_surface, {{false, {{0, {owner(0), owner(0)}}}}})),
            std::string(kPrefix) + "the loops hold more trims than the trim count 1");
  EXPECT_EQ(error(v2_brep({1, 1, 1, 1}, one_curve, one_edge, one_surface, {{false, {{0, {owner(5)}}}}})),
            std::string(kPrefix) + "a trim owning edge 5 of 1 edges");
  EXPECT_EQ(error(v2_brep({1, 1, 1, 1}, one_curve, one_edge, one_surface, {{false, {}}})),
            std::string(kPrefix) + "face loop count 0 is below 1");
  EXPECT_EQ(error(v2_brep({1, 1, 1, 1000000}, one_curve, one_edge, one_surface, {}))
                .rfind(std::string(kPrefix) + "1000000 trim cannot fit", 0),
            0u);
}

}  // namespace
}  // namespace cadnurbs::rhino
