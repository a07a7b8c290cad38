// scene_from_3dm on hand-built files: layers and object nodes, edge numbers offset per Brep, lengths in
// millimetres, and a face that cannot be trimmed NURBS becoming Rhino's render mesh (or left out, said).
#include <gtest/gtest.h>

#include "formats/3dm/rhino_scene.hpp"

namespace cadnurbs::rhino {
namespace {

// The unit square z = 0 as a bilinear patch, trimmed by its domain loop with edges `first`..`first + 3`.
TrimmedSurface square(int first_edge) {
  NurbsSurface s;
  s.u_count = s.v_count = 2;
  s.u_knots = s.v_knots = {0, 0, 1, 1};
  s.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  TrimmedSurface face{s, {domain_loop(s)}};
  for (int k = 0; k < 4; ++k) face.loops[0].edges.push_back({first_edge + k, false});
  return face;
}

// A loop shaped like a bow tie: it crosses itself, which repair_trimming_loops refuses.
TrimmedSurface bow_tie() {
  TrimmedSurface face = square(0);
  face.loops[0].segments = {Polyline2D{{{0.1, 0.1}, {0.9, 0.9}, {0.9, 0.1}, {0.1, 0.6}, {0.1, 0.1}}}};
  face.loops[0].edges.clear();
  return face;
}

TriangleMesh triangle_mesh() {
  TriangleMesh m;
  m.positions = {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  m.triangles = {{0, 1, 2}};
  return m;
}

Rhino3dmFile two_breps_in_centimetres() {
  Rhino3dmFile file;
  file.unit = {"cm", 10.0};
  file.layers = {{"Default", {0, 0, 0}}, {"Parts", {1, 0, 0}}};
  RhinoBrep first;  // faces 1 and 3 built; face 2 skipped by the reader, with a render mesh
  first.faces = {square(0), square(4)};
  first.face_indices = {0, 2};
  first.edge_count = 8;
  first.skipped_faces = {"face 2: surface 1 is missing"};
  first.skipped_face_indices = {1};
  first.render_meshes = {std::nullopt, triangle_mesh(), std::nullopt};
  RhinoBrep second;  // face 1 built; face 2 crosses itself and has no render mesh
  second.faces = {square(0), bow_tie()};
  second.face_indices = {0, 1};
  second.edge_count = 4;
  file.objects.push_back({0, "ON_Brep", first, {"bracket", 1, std::nullopt}});
  file.objects.push_back({1, "ON_Brep", second, {"", 7, Colour{0, 0, 1}}});
  file.objects.push_back({2, "ON_SubD", Unsupported{"ON_SubD"}, {"blob", 0, std::nullopt}});
  file.warnings = {"object 2 (ON_SubD): not supported, skipped"};
  return file;
}

TEST(RhinoScene, LayersObjectsEdgesAndUnits) {
  const RhinoScene read = scene_from_3dm(two_breps_in_centimetres(), "part");
  const Scene& scene = read.scene;
  EXPECT_EQ(scene.root.name, "part");
  EXPECT_EQ(scene.unit.name, "mm");
  EXPECT_EQ(scene.source_unit.name, "cm");
  // Object 1's layer 7 is not in the table: it sits at the root, before the layer nodes that hold objects.
  ASSERT_EQ(scene.root.children.size(), 2u);
  const SceneNode& loose = scene.root.children[0];
  EXPECT_EQ(loose.source_entity, "object 1");
  ASSERT_TRUE(loose.colour.has_value());
  EXPECT_EQ(loose.colour->b, 1.0);
  const SceneNode& parts = scene.root.children[1];
  EXPECT_EQ(parts.name, "Parts");
  EXPECT_EQ(parts.colour->r, 1.0);
  ASSERT_EQ(parts.children.size(), 1u);
  const SceneNode& bracket = parts.children[0];
  EXPECT_EQ(bracket.name, "bracket");
  ASSERT_EQ(bracket.shapes.size(), 3u);
  EXPECT_EQ(bracket.shapes[0].source_entity, "face 2 (mesh)");
  EXPECT_EQ(bracket.shapes[1].source_entity, "face 1");
  EXPECT_EQ(bracket.shapes[2].source_entity, "face 3");
  // Centimetres to millimetres: the square's far corner and the render mesh scale by 10.
  const auto& face3 = std::get<TrimmedSurface>(bracket.shapes[2].geometry);
  EXPECT_EQ(face3.surface.points[3], Eigen::Vector3d(10, 10, 0));
  EXPECT_EQ(std::get<TriangleMesh>(bracket.shapes[0].geometry).positions[1], Eigen::Vector3d(10, 0, 10));
  // Edges: the first Brep's 8, then the second Brep's from 8 on.
  EXPECT_EQ(face3.loops[0].edges[3].edge, 7);
  const auto& second_face = std::get<TrimmedSurface>(loose.shapes[0].geometry);
  EXPECT_EQ(second_face.loops[0].edges[0].edge, 8);
  EXPECT_EQ(read.edge_count, 12);
}

TEST(RhinoScene, FacesThatCannotBeNurbsAreMeshedOrLeftOutAndSaid) {
  const RhinoScene read = scene_from_3dm(two_breps_in_centimetres(), "part");
  EXPECT_EQ(read.face_count, 4);  // 3 trimmed NURBS + 1 render mesh
  EXPECT_EQ(read.skipped_faces, 1);
  ASSERT_EQ(read.meshed_faces.size(), 1u);
  EXPECT_EQ(read.meshed_faces[0].object, "object 0 'bracket'");
  EXPECT_EQ(read.meshed_faces[0].face, 2);
  EXPECT_EQ(read.meshed_faces[0].reason, "surface 1 is missing");
  ASSERT_EQ(read.warnings.size(), 2u);
  EXPECT_EQ(read.warnings[0], "object 2 (ON_SubD): not supported, skipped");
  EXPECT_EQ(read.warnings[1].rfind("object 1 face 2: left out (no render mesh): ", 0), 0u) << read.warnings[1];
  EXPECT_NE(read.warnings[1].find("cross"), std::string::npos) << read.warnings[1];
  EXPECT_EQ(read.warnings[1].find("face 2", 10), std::string::npos) << "named once: " << read.warnings[1];
}

}  // namespace
}  // namespace cadnurbs::rhino
