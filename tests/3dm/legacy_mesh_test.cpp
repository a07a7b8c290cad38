// Rhino 1's meshes (legacy_mesh.hpp): object chunks built here byte by byte in the layout openNURBS's
// ReadV1_TCODE_MESH_OBJECT reads, so every vertex, face and normal has a closed form to check. The files with V1 meshes
// (openNURBS's example_files/V1) are not in the corpus; the long tier converts them when CADNURBS_OPENNURBS_EXAMPLES
// names their folder.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

#include "formats/3dm/legacy_objects.hpp"
#include "formats/3dm/typecodes.hpp"

namespace cadnurbs::rhino {
namespace {

template <typename T>
void put(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

// A version 1 chunk: typecode, int32 length, body.
std::string chunk(std::uint32_t typecode, const std::string& body) {
  std::string out;
  put(out, typecode);
  put(out, static_cast<std::int32_t>(body.size()));
  return out + body;
}

std::string short_chunk(std::uint32_t typecode, std::int32_t value) {
  std::string out;
  put(out, typecode);
  put(out, value);
  return out;
}

struct V1Mesh {
  std::vector<std::array<std::uint16_t, 3>> vertices;  // quantised to the box
  std::vector<std::array<std::uint16_t, 4>> faces;
  std::vector<std::array<std::int8_t, 3>> normals;  // empty: none
  Eigen::Vector3d low{-1, 2, 0}, high{3, 4, 10};
  std::int32_t declared_vertices = -1;  // -1: the vertices' count
};

std::string geometry_chunk(const V1Mesh& m) {
  std::string body;
  put(body, m.declared_vertices < 0 ? static_cast<std::int32_t>(m.vertices.size()) : m.declared_vertices);
  put(body, static_cast<std::int32_t>(m.faces.size()));
  put(body, static_cast<std::int32_t>(!m.normals.empty()));
  put(body, std::int32_t{0});  // no texture coordinates
  for (const auto* p : {&m.low, &m.high})
    for (int k = 0; k < 3; ++k) put(body, (*p)[k]);
  for (const auto& v : m.vertices)
    for (const auto q : v) put(body, q);
  for (const auto& f : m.faces)
    for (const auto i : f) put(body, i);
  for (const auto& n : m.normals)
    for (const auto c : n) put(body, c);
  return chunk(tcode::kCompressedMeshGeometry, body);
}

// The object chunk: the geometry, then (as Rhino 1 writes a mesh's) the layer reference after it.
ObjectRecord read_object(const V1Mesh& m, std::vector<std::string>& warnings) {
  const std::string bytes = chunk(
      tcode::kMeshObject, geometry_chunk(m) + short_chunk(tcode::kLayerRef, 2) + short_chunk(tcode::kEndOfTable, 0));
  ArchiveReader reader(bytes, "v1.3dm", 1);
  const ChunkHeader h = reader.begin_chunk();
  return read_v1_object(bytes, "v1.3dm", h, 7, warnings);
}

V1Mesh quad_and_triangle() {
  V1Mesh m;
  m.vertices = {{0, 0, 0}, {65535, 0, 0}, {65535, 65535, 0}, {0, 65535, 65535}, {32768, 16384, 65535}};
  m.faces = {{0, 1, 2, 3}, {1, 4, 2, 2}};
  return m;
}

TEST(LegacyMesh, VerticesAreTheBoxFractionsAndQuadsSplitInTwo) {
  std::vector<std::string> warnings;
  V1Mesh m = quad_and_triangle();
  m.normals = {{127, 0, 0}, {0, -127, 0}, {0, 0, 127}, {127, 0, 0}, {0, 0, -127}};
  const ObjectRecord object = read_object(m, warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  EXPECT_EQ(object.class_name, "ON_Mesh");
  EXPECT_EQ(object.attributes.layer_index, 2);  // read after the geometry chunk
  const auto* mesh = std::get_if<TriangleMesh>(&object.geometry);
  ASSERT_NE(mesh, nullptr);
  ASSERT_EQ(mesh->positions.size(), 5u);
  const Eigen::Vector3d size = m.high - m.low;
  for (std::size_t v = 0; v < 5; ++v) {
    const Eigen::Vector3d q(m.vertices[v][0], m.vertices[v][1], m.vertices[v][2]);
    const Eigen::Vector3d expected = m.low + q.cwiseProduct(size) / 65535.0;
    EXPECT_LT((mesh->positions[v] - expected).norm(), 1e-12) << "vertex " << v;
  }
  // The quad 0 1 2 3 as 0 1 2 and 0 2 3; the triangle (third index repeated) as one.
  const std::vector<std::array<int, 3>> triangles = {{0, 1, 2}, {0, 2, 3}, {1, 4, 2}};
  EXPECT_EQ(mesh->triangles, triangles);
  ASSERT_EQ(mesh->corner_normals.size(), 9u);
  EXPECT_EQ(mesh->corner_normals[4], Eigen::Vector3d(0, 0, 1));   // triangle 1, corner 1: vertex 2
  EXPECT_EQ(mesh->corner_normals[7], Eigen::Vector3d(0, 0, -1));  // triangle 2, corner 1: vertex 4
}

TEST(LegacyMesh, AFaceIndexPastTheVerticesIsRefusedNamingTheFace) {
  std::vector<std::string> warnings;
  V1Mesh m = quad_and_triangle();
  m.faces[1] = {1, 5, 2, 2};
  const ObjectRecord object = read_object(m, warnings);
  EXPECT_TRUE(std::holds_alternative<Unsupported>(object.geometry));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0],
            "object 7 (ON_Mesh): v1.3dm: chunk 0x00100017 at offset 8: V1 "
            "mesh: face 1 has vertex index 5, the mesh has "
            "5 vertices; skipped");
}

TEST(LegacyMesh, AVertexCountLargerThanTheChunkIsRefusedBeforeAllocating) {
  std::vector<std::string> warnings;
  V1Mesh m = quad_and_triangle();
  m.declared_vertices = 2'000'000'000;
  const ObjectRecord object = read_object(m, warnings);
  EXPECT_TRUE(std::holds_alternative<Unsupported>(object.geometry));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("V1 mesh: 2000000000 vertices need 12000000000 bytes"), std::string::npos) << warnings[0];
}

}  // namespace
}  // namespace cadnurbs::rhino
