#include "formats/3dm/legacy_mesh.hpp"

#include <cstdint>

#include "formats/3dm/mesh_faces.hpp"

namespace cadnurbs::rhino {

TriangleMesh read_legacy_mesh(ArchiveReader& reader) {
  const auto refuse = [&](const std::string& reason) { reader.fail("V1 mesh: " + reason); };
  const std::int32_t vcount = reader.i32();
  const std::int32_t fcount = reader.i32();
  if (vcount <= 0 || fcount <= 0)
    refuse("counts must be positive (" + std::to_string(vcount) + " vertices, " + std::to_string(fcount) + " faces)");
  const bool has_normals = reader.i32() != 0;
  const bool has_texture = reader.i32() != 0;
  const Eigen::Vector3d low = reader.point3();
  const Eigen::Vector3d high = reader.point3();
  if (!low.allFinite() || !high.allFinite()) refuse("bounding box is not finite");
  const auto vertex_count = static_cast<std::size_t>(vcount);
  if (vertex_count > reader.bytes_left() / 6)
    refuse(std::to_string(vertex_count) + " vertices need " + std::to_string(vertex_count * 6) + " bytes, " +
           std::to_string(reader.bytes_left()) + " left");

  TriangleMesh mesh;
  mesh.positions.resize(vertex_count);
  const Eigen::Vector3d step = (high - low) / 65535.0;
  for (auto& p : mesh.positions) {
    const double qx = reader.u16(), qy = reader.u16(), qz = reader.u16();
    p = low + Eigen::Vector3d(qx, qy, qz).cwiseProduct(step);
  }
  const int index_size = vertex_count < 65535 ? 2 : 4;
  mesh.triangles = read_mesh_faces(reader, static_cast<std::size_t>(fcount), vertex_count, index_size, "V1 mesh");
  if (has_normals) {
    if (vertex_count > reader.bytes_left() / 3) refuse("normals run past the chunk");
    std::vector<Eigen::Vector3d> normals(vertex_count);
    for (auto& n : normals) {
      const double x = static_cast<std::int8_t>(reader.u8()), y = static_cast<std::int8_t>(reader.u8()),
                   z = static_cast<std::int8_t>(reader.u8());
      n = Eigen::Vector3d(x, y, z) / 127.0;
    }
    mesh.corner_normals = vertex_to_corner_normals(normals, mesh.triangles);
  }
  if (has_texture) reader.skip(vertex_count * 4);
  return mesh;
}

}  // namespace cadnurbs::rhino
