#include "formats/3dm/mesh_object.hpp"

#include <array>
#include <cmath>
#include <cstring>

#include "formats/3dm/compressed_buffer.hpp"
#include "formats/3dm/mesh_faces.hpp"
#include "formats/3dm/typecodes.hpp"

namespace cadnurbs::rhino {
namespace {

[[noreturn]] void refuse(const ArchiveReader& reader, const std::string& reason) { reader.fail("ON_Mesh: " + reason); }

// An optional sub-object (mesh parameters, curvature statistics): a flag byte, then a chunk when set.
void skip_flagged_chunk(ArchiveReader& reader) {
  if (reader.u8() != 0) {
    reader.begin_chunk(tcode::kAnonymousChunk);
    reader.end_chunk();
  }
}

std::vector<Eigen::Vector3d> float_points(std::string_view bytes) {
  std::vector<Eigen::Vector3d> points(bytes.size() / 12);
  for (std::size_t i = 0; i < points.size(); ++i) {
    float xyz[3];
    std::memcpy(xyz, bytes.data() + 12 * i, 12);
    points[i] = {xyz[0], xyz[1], xyz[2]};
  }
  return points;
}

// openNURBS keeps the double-precision vertices only where they agree with the floats (to 1e-6 of the
// largest coordinate); some files hold stale ones. Returns false (keep the floats) otherwise.
bool doubles_agree(const std::vector<Eigen::Vector3d>& floats, const std::vector<Eigen::Vector3d>& doubles) {
  if (floats.size() != doubles.size()) return false;
  for (std::size_t i = 0; i < floats.size(); ++i) {
    const Eigen::Vector3f rounded = doubles[i].cast<float>();
    const double largest = floats[i].cwiseAbs().maxCoeff();
    if ((rounded.cast<double>() - floats[i]).cwiseAbs().maxCoeff() > largest * 1e-6) return false;
  }
  return true;
}

// The 3.7 double-precision vertex chunk: version, uint32 count, a compressed buffer of count * 24 bytes.
std::vector<Eigen::Vector3d> read_double_vertices(ArchiveReader& reader, std::size_t vertex_count) {
  const auto [major, minor] = reader.begin_versioned_chunk(tcode::kAnonymousChunk);
  (void)minor;
  std::vector<Eigen::Vector3d> points;
  if (major == 1) {
    const std::uint32_t count = reader.u32();
    if (count != 0) {
      if (count != vertex_count)
        refuse(reader, "double-precision vertex count " + std::to_string(count) + " is not the vertex count " +
                           std::to_string(vertex_count));
      const std::string bytes = read_compressed_buffer(reader, std::size_t{count} * 24, "ON_Mesh double vertex buffer");
      // An absent buffer (declared size 0) with a count that is not: found by fuzz_3dm (read past the end).
      if (bytes.size() != std::size_t{count} * 24)
        refuse(reader, "double-precision vertex buffer missing for " + std::to_string(count) + " vertices");
      points.resize(count);
      for (std::size_t i = 0; i < count; ++i) {
        double xyz[3];
        std::memcpy(xyz, bytes.data() + 24 * i, 24);
        points[i] = {xyz[0], xyz[1], xyz[2]};
      }
    }
  }
  reader.end_chunk();
  return points;
}

}  // namespace

TriangleMesh read_mesh(ArchiveReader& reader) {
  const auto [major, minor] = reader.chunk_version();
  if (major != 1 && major != 3) refuse(reader, "chunk version " + std::to_string(major) + "." + std::to_string(minor) + " is not 1.x or 3.x");
  const std::int32_t vcount = reader.i32();
  const std::int32_t fcount = reader.i32();
  if (vcount < 0 || fcount < 0)
    refuse(reader, "negative count (" + std::to_string(vcount) + " vertices, " + std::to_string(fcount) + " faces)");
  // Texture and surface domains (4 intervals), surface scale (2 doubles), vertex, normal and texture
  // boxes (6 + 6 + 4 floats), the closed flag.
  reader.skip(4 * 16 + 2 * 8 + 16 * 4 + 4);
  skip_flagged_chunk(reader);                          // mesh parameters
  for (int k = 0; k < 4; ++k) skip_flagged_chunk(reader);  // curvature statistics
  const auto vertex_count = static_cast<std::size_t>(vcount);

  TriangleMesh mesh;
  mesh.triangles = read_mesh_faces(reader, static_cast<std::size_t>(fcount), vertex_count, reader.i32(), "ON_Mesh");
  if (major == 1) {
    // Plain arrays (count, then x y z floats): vertices, then normals (none or one per vertex); texture
    // coordinates, curvatures and colours follow and are left unread.
    const std::size_t n = reader.count(12);
    if (n != vertex_count) refuse(reader, "vertex array holds " + std::to_string(n) + " points, expected " + std::to_string(vertex_count));
    mesh.positions = float_points(reader.raw(n * 12));
    const std::size_t normal_count = reader.count(12);
    const std::vector<Eigen::Vector3d> normals = float_points(reader.raw(normal_count * 12));
    if (normal_count == vertex_count) mesh.corner_normals = vertex_to_corner_normals(normals, mesh.triangles);
    return mesh;
  }
  if (vertex_count > 0) {
    mesh.positions = float_points(read_compressed_buffer(reader, vertex_count * 12, "ON_Mesh vertex buffer"));
    if (mesh.positions.size() != vertex_count) refuse(reader, "vertex buffer missing");
    const std::vector<Eigen::Vector3d> normals =
        float_points(read_compressed_buffer(reader, vertex_count * 12, "ON_Mesh normal buffer"));
    if (!normals.empty()) mesh.corner_normals = vertex_to_corner_normals(normals, mesh.triangles);
    for (int k = 0; k < 3; ++k) skip_compressed_buffer(reader);  // texture coordinates, curvatures, colours
  }
  if (minor >= 2) reader.i32();  // packed texture rotation
  if (minor >= 3) {
    reader.uuid();  // texture mapping id
    if (vertex_count > 0) skip_compressed_buffer(reader);  // surface parameters
  }
  if (minor >= 4) {
    // openNURBS reads these from files written from June 2006 on, the only ones with mesh version 3.4+.
    reader.begin_chunk(tcode::kAnonymousChunk);  // texture mapping tag
    reader.end_chunk();
  }
  if (minor >= 5) reader.skip(3);  // manifold, oriented, solid flags
  if (minor >= 6 && reader.boolean()) {
    reader.begin_chunk(tcode::kAnonymousChunk);  // n-gons
    reader.end_chunk();
  }
  if (minor >= 7 && reader.boolean()) {
    std::vector<Eigen::Vector3d> doubles = read_double_vertices(reader, vertex_count);
    if (doubles_agree(mesh.positions, doubles)) mesh.positions = std::move(doubles);
  }
  return mesh;
}

}  // namespace cadnurbs::rhino
