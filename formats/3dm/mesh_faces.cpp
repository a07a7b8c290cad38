#include "formats/3dm/mesh_faces.hpp"

#include <cstdint>

namespace cadnurbs::rhino {

std::vector<std::array<int, 3>> read_mesh_faces(ArchiveReader& reader, std::size_t face_count, std::size_t vertex_count,
                                                int index_size, const std::string& entity) {
  const auto refuse = [&](const std::string& reason) { reader.fail(entity + ": " + reason); };
  if (face_count == 0) return {};
  if (index_size != 1 && index_size != 2 && index_size != 4)
    refuse("face index size " + std::to_string(index_size) + " is not 1, 2 or 4");
  const std::size_t face_bytes = 4 * static_cast<std::size_t>(index_size);
  if (face_count > reader.bytes_left() / face_bytes)
    refuse(std::to_string(face_count) + " faces need " + std::to_string(face_count * face_bytes) + " bytes, " +
           std::to_string(reader.bytes_left()) + " left");
  std::vector<std::array<int, 3>> triangles;
  triangles.reserve(face_count * 2);
  for (std::size_t f = 0; f < face_count; ++f) {
    std::uint32_t vi[4];
    for (auto& v : vi) v = index_size == 1 ? reader.u8() : index_size == 2 ? reader.u16() : reader.u32();
    for (const std::uint32_t v : vi)
      if (v >= vertex_count)
        refuse("face " + std::to_string(f) + " has vertex index " + std::to_string(v) + ", the mesh has " +
               std::to_string(vertex_count) + " vertices");
    const auto i = [&](int k) { return static_cast<int>(vi[k]); };
    triangles.push_back({i(0), i(1), i(2)});
    if (vi[2] != vi[3]) triangles.push_back({i(0), i(2), i(3)});
  }
  return triangles;
}

std::vector<Eigen::Vector3d> vertex_to_corner_normals(const std::vector<Eigen::Vector3d>& vertex_normals,
                                                      const std::vector<std::array<int, 3>>& triangles) {
  for (const auto& n : vertex_normals)
    if (!n.allFinite() || n.squaredNorm() == 0) return {};
  std::vector<Eigen::Vector3d> out;
  out.reserve(3 * triangles.size());
  for (const auto& t : triangles)
    for (const int v : t) out.push_back(vertex_normals[static_cast<std::size_t>(v)]);
  return out;
}

}  // namespace cadnurbs::rhino
