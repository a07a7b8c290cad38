// ON_Mesh objects in files Rhino wrote. Reference figures from McNeel's rhino3dm 8 (npm, OpenNURBS) reading
// the same files: vertex count, face count (triangles + quads), bounding box.
#include "formats/3dm/mesh_object.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "class_chunks.hpp"
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

}  // namespace
}  // namespace cadnurbs::rhino
