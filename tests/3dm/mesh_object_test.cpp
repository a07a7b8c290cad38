// ON_Mesh objects in files Rhino wrote and hand-built ones. Reference figures from McNeel's rhino3dm 8 (npm, OpenNURBS) reading
// the same files: vertex count, face count (triangles + quads), bounding box.
#include "formats/3dm/mesh_object.hpp"

#include <gtest/gtest.h>

#include <zlib.h>

#include <Eigen/Geometry>
#include <cstring>

#include "class_chunks.hpp"
#include "formats/3dm/typecodes.hpp"
#include "formats/common/file_io.hpp"

namespace cadnurbs::rhino {
namespace {

constexpr const char* kMeshClass = "4ED7D4E4-E947-11D3-BFE5-0010830122F0";

std::vector<TriangleMesh> meshes_in(const std::string& file) {
  const std::string path = CADNURBS_SHARED_DIR "/corpus/3dm/" + file;
  const std::string bytes = read_file(path);
  std::vector<TriangleMesh> out;
  for (const std::size_t offset : testing::class_chunk_offsets(bytes, kMeshClass)) {
    ArchiveReader reader = testing::reader_at_class_data(bytes, path, offset);
    out.push_back(read_mesh(reader));
    validate(out.back(), file);
  }
  return out;
}

Eigen::AlignedBox3d box_of(const TriangleMesh& mesh) {
  Eigen::AlignedBox3d box;
  for (const auto& p : mesh.positions) box.extend(p);
  return box;
}

TEST(MeshObject, Rhino8SphereMeshMatchesRhino3dm) {
  const auto meshes = meshes_in("mesh.3dm");
  ASSERT_EQ(meshes.size(), 1u);
  const TriangleMesh& mesh = meshes[0];
  EXPECT_EQ(mesh.positions.size(), 420u);
  EXPECT_EQ(mesh.triangles.size(), 276u);  // 276 triangle faces, no quads
  const Eigen::AlignedBox3d box = box_of(mesh);
  // rhino3dm's box, from the mesh's double-precision vertices; single precision would miss by ~1e-6.
  const double h = 25.12594806839283;
  EXPECT_NEAR(box.min().x(), -h, 1e-12);
  EXPECT_NEAR(box.max().z(), h, 1e-12);
  for (const auto& p : mesh.positions) EXPECT_NEAR(p.norm(), 25.5047, 1e-4);  // all on one sphere
  ASSERT_EQ(mesh.corner_normals.size(), 3 * mesh.triangles.size());
  double radial_min = 1, face_min = 1, length_min = 2, length_max = 0;
  for (std::size_t c = 0; c < mesh.corner_normals.size(); ++c) {
    const auto& t = mesh.triangles[c / 3];
    const auto p = [&](int k) { return mesh.positions[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])]; };
    const Eigen::Vector3d face = (p(1) - p(0)).cross(p(2) - p(0)).normalized();
    const Eigen::Vector3d n = mesh.corner_normals[c];
    radial_min = std::min(radial_min, n.normalized().dot(p(static_cast<int>(c % 3)).normalized()));
    face_min = std::min(face_min, n.normalized().dot(face));
    length_min = std::min(length_min, n.norm()), length_max = std::max(length_max, n.norm());
  }
  // The mesh is flat-shaded (unwelded corners): its stored unit normals are its triangles' normals, so the
  // split keeps Rhino's orientation, and they point out of the sphere.
  EXPECT_GT(face_min, 0.99999);
  EXPECT_NEAR(length_min, 1.0, 1e-6);
  EXPECT_NEAR(length_max, 1.0, 1e-6);
  EXPECT_GT(radial_min, 0.96);
}

TEST(MeshObject, QuadsSplitInTwoInTheRhino6SubdLogoMeshes) {
  const auto meshes = meshes_in("v6_rhino_subd_logo.3dm");
  ASSERT_EQ(meshes.size(), 6u);
  // rhino3dm: vertices, triangle faces, quad faces per mesh.
  const int expected[6][3] = {{174, 36, 138}, {294, 16, 284}, {236, 24, 211}, {80, 0, 40}, {80, 0, 40}, {40, 0, 18}};
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(meshes[i].positions.size(), static_cast<std::size_t>(expected[i][0])) << "mesh " << i;
    EXPECT_EQ(meshes[i].triangles.size(), static_cast<std::size_t>(expected[i][1] + 2 * expected[i][2])) << "mesh " << i;
  }
  const Eigen::AlignedBox3d box = box_of(meshes[0]);
  EXPECT_NEAR(box.min().x(), -14.731868743896484, 1e-12);
  EXPECT_NEAR(box.max().z(), 13.509560585021973, 1e-12);
}

// The render meshes Rhino cached on each Brep face (ON_Mesh objects inside the Brep's data); rhino3dm's
// BrepFace.getMesh(Render) gives the same counts, summed over the faces.
TEST(MeshObject, CachedRenderMeshesOfBrepFaces) {
  struct Case {
    const char* file;
    std::size_t meshes, vertices, triangles;
  };
  for (const Case& c : {Case{"v4_MechPartA.3dm", 41, 7839, 12614}, Case{"v7_rhino_logo_nurbs.3dm", 22, 17756, 32044}}) {
    SCOPED_TRACE(c.file);
    const auto meshes = meshes_in(c.file);
    std::size_t vertices = 0, triangles = 0;
    for (const auto& m : meshes) vertices += m.positions.size(), triangles += m.triangles.size();
    EXPECT_EQ(meshes.size(), c.meshes);
    EXPECT_EQ(vertices, c.vertices);
    EXPECT_EQ(triangles, c.triangles);
  }
}

// Hand-built ON_Mesh class data (archive version 4: 4-byte chunk lengths) for the layouts and refusals.
struct MeshBytes {
  std::string s;
  template <class T>
  MeshBytes& put(T v) {
    s.append(reinterpret_cast<const char*>(&v), sizeof v);
    return *this;
  }
  // Version byte, counts, the domains/boxes/closed flag (zeros), no mesh parameters or curvature stats.
  MeshBytes(std::uint8_t version, std::int32_t vcount, std::int32_t fcount) {
    put(version).put(vcount).put(fcount);
    s.append(148 + 5, '\0');
  }
};

const float kSquare[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};

std::string error_of(const std::string& bytes) {
  try {
    ArchiveReader reader(bytes, "m.3dm", 4);
    read_mesh(reader);
  } catch (const ArchiveError& e) {
    return e.what();
  }
  return "no error";
}

TEST(MeshObject, PlainArraysOfVersion1AndAQuadSplitInTwo) {
  MeshBytes b(0x10, 4, 1);
  b.put(std::int32_t{2}).put(std::uint16_t{0}).put(std::uint16_t{1}).put(std::uint16_t{2}).put(std::uint16_t{3});
  b.put(std::int32_t{4});
  for (const auto& p : kSquare) b.put(p[0]).put(p[1]).put(p[2]);
  b.put(std::int32_t{4});  // vertex normals: all +z but the third, -z (to tell corners apart)
  for (int v = 0; v < 4; ++v) b.put(0.0f).put(0.0f).put(v == 2 ? -1.0f : 1.0f);
  ArchiveReader reader(b.s, "m.3dm", 4);
  const TriangleMesh mesh = read_mesh(reader);
  ASSERT_EQ(mesh.positions.size(), 4u);
  EXPECT_EQ(mesh.positions[2], Eigen::Vector3d(1, 1, 0));
  ASSERT_EQ(mesh.corner_normals.size(), 6u);  // per corner, following the split: 0 1 2, 0 2 3
  EXPECT_EQ(mesh.corner_normals[2], Eigen::Vector3d(0, 0, -1));
  EXPECT_EQ(mesh.corner_normals[4], Eigen::Vector3d(0, 0, -1));
  EXPECT_EQ(mesh.corner_normals[5], Eigen::Vector3d(0, 0, 1));
  ASSERT_EQ(mesh.triangles.size(), 2u);
  EXPECT_EQ(mesh.triangles[0], (std::array<int, 3>{0, 1, 2}));
  EXPECT_EQ(mesh.triangles[1], (std::array<int, 3>{0, 2, 3}));
  EXPECT_DOUBLE_EQ(mesh_area(mesh), 1.0);
}

TEST(MeshObject, CompressedVertexBufferOfVersion3) {
  std::string raw(reinterpret_cast<const char*>(kSquare), sizeof kSquare);
  uLongf packed_size = compressBound(static_cast<uLong>(raw.size()));
  std::string packed(packed_size, '\0');
  ASSERT_EQ(compress(reinterpret_cast<Bytef*>(packed.data()), &packed_size, reinterpret_cast<const Bytef*>(raw.data()),
                     static_cast<uLong>(raw.size())),
            Z_OK);
  packed.resize(packed_size);
  const auto crc = [](const std::string& x) {
    return static_cast<std::uint32_t>(::crc32(0, reinterpret_cast<const Bytef*>(x.data()), static_cast<uInt>(x.size())));
  };
  MeshBytes b(0x30, 4, 2);  // version 3.0: two triangles, 1-byte indices
  b.put(std::int32_t{1});
  for (std::uint8_t i : {0, 1, 2, 2, 0, 2, 3, 3}) b.put(i);
  b.put(static_cast<std::uint32_t>(raw.size())).put(crc(raw)).put(std::uint8_t{1});
  b.put(tcode::kAnonymousChunk).put(static_cast<std::uint32_t>(packed.size() + 4));
  b.s += packed;
  b.put(crc(packed));
  for (int k = 0; k < 4; ++k) b.put(std::uint32_t{0});  // no normals, texture coordinates, curvatures, colours
  ArchiveReader reader(b.s, "m.3dm", 4);
  const TriangleMesh mesh = read_mesh(reader);
  ASSERT_EQ(mesh.positions.size(), 4u);
  EXPECT_EQ(mesh.positions[3], Eigen::Vector3d(0, 1, 0));
  EXPECT_EQ(mesh.triangles.size(), 2u);
  EXPECT_EQ(reader.offset(), b.s.size());

  // The same with a corrupted inflated CRC.
  std::string bad = b.s;
  bad[MeshBytes(0x30, 4, 2).s.size() + 4 + 8 + 4] ^= 1;
  EXPECT_EQ(error_of(bad), "m.3dm: offset " + std::to_string(MeshBytes(0x30, 4, 2).s.size() + 4 + 8 + 9 + 8 + packed.size() + 4) +
                               ": ON_Mesh vertex buffer: CRC mismatch of the inflated bytes");
}

TEST(MeshObject, RefusesBadIndicesAndImpossibleBufferSizes) {
  MeshBytes face(0x10, 4, 1);
  face.put(std::int32_t{4}).put(std::uint32_t{0}).put(std::uint32_t{1}).put(std::uint32_t{4}).put(std::uint32_t{4});
  EXPECT_EQ(error_of(face.s), "m.3dm: offset 182: ON_Mesh: face 0 has vertex index 4, the mesh has 4 vertices");

  MeshBytes size(0x30, 4, 0);
  size.put(std::int32_t{0}).put(std::uint32_t{13});
  EXPECT_EQ(error_of(size.s), "m.3dm: offset " + std::to_string(size.s.size()) +
                                  ": ON_Mesh vertex buffer: declared size 13 bytes, expected 48");

  // 100,000 vertices (1.2 MB) claimed from a 10-byte zlib stream: refused before inflating or allocating.
  MeshBytes ratio(0x30, 100000, 0);
  ratio.put(std::int32_t{0}).put(std::uint32_t{1200000}).put(std::uint32_t{0}).put(std::uint8_t{1});
  ratio.put(tcode::kAnonymousChunk).put(std::uint32_t{14});
  ratio.s.append(14, '\0');
  EXPECT_EQ(error_of(ratio.s), "m.3dm: chunk 0x40008000 at offset " + std::to_string(ratio.s.size() - 22) +
                                   ": ON_Mesh vertex buffer: 10 compressed bytes cannot inflate to 1200000");

  // Version 3.7 with the double-precision vertices present but their buffer absent (declared size 0)
  // while the count says 1: the reader copied 24 bytes out of an empty buffer (found by fuzz_3dm).
  const auto crc = [](const std::string& x) {
    return static_cast<std::uint32_t>(::crc32(0, reinterpret_cast<const Bytef*>(x.data()), static_cast<uInt>(x.size())));
  };
  MeshBytes doubles(0x37, 1, 0);
  doubles.put(std::int32_t{0});                                                 // no faces: no index size
  doubles.put(std::uint32_t{12}).put(crc(std::string(12, '\0'))).put(std::uint8_t{0});
  doubles.s.append(12, '\0');                                                   // one float vertex, stored
  for (int k = 0; k < 4; ++k) doubles.put(std::uint32_t{0});                    // normals, textures, curvatures, colours
  doubles.put(std::int32_t{0}).s.append(16, '\0');                              // packed rotation, mapping id
  doubles.put(std::uint32_t{0});                                                // surface parameters
  doubles.put(tcode::kAnonymousChunk).put(std::uint32_t{4}).put(std::uint32_t{0});  // mapping tag: empty, CRC 0
  doubles.s.append(3, '\0');                                                    // manifold, oriented, solid
  doubles.put(std::uint8_t{0}).put(std::uint8_t{1});                            // no n-gons; double vertices
  MeshBytes body(0, 0, 0);
  body.s.clear();
  body.put(std::int32_t{1}).put(std::int32_t{0}).put(std::uint32_t{1}).put(std::uint32_t{0});
  doubles.put(tcode::kAnonymousChunk).put(static_cast<std::uint32_t>(body.s.size() + 4));
  doubles.s += body.s;
  doubles.put(crc(body.s));
  const std::string missing = error_of(doubles.s);
  EXPECT_EQ(missing.rfind("m.3dm: ", 0), 0u) << missing;
  EXPECT_NE(missing.find("ON_Mesh: double-precision vertex buffer missing for 1 vertices"), std::string::npos) << missing;

  MeshBytes version(0x20, 0, 0);
  EXPECT_EQ(error_of(version.s), "m.3dm: offset 1: ON_Mesh: chunk version 2.0 is not 1.x or 3.x");
}

}  // namespace
}  // namespace cadnurbs::rhino
