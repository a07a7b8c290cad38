#include "formats/ply/ply_writer.hpp"

#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <tuple>

#include "core/geometry_error.hpp"
#include "formats/common/file_io.hpp"

namespace cadnurbs {

namespace {

void put_float(std::string& out, double x) {
  const float f = static_cast<float>(x);
  char bytes[4];
  std::memcpy(bytes, &f, 4);  // x86 and every platform we build on are little-endian
  out.append(bytes, 4);
}

void put_uint(std::string& out, uint32_t x) {
  char bytes[4];
  std::memcpy(bytes, &x, 4);
  out.append(bytes, 4);
}

}  // namespace

std::string format_ply(const TriangleMesh& mesh, const std::string& comment) {
  validate(mesh, "mesh");
  for (size_t i = 0; i < mesh.positions.size(); ++i)
    if (mesh.positions[i].cwiseAbs().maxCoeff() > std::numeric_limits<float>::max())
      throw GeometryError("mesh", "vertex " + std::to_string(i) + " is beyond float range");
  const bool normals = !mesh.corner_normals.empty();
  // Vertex = (position index, normal as float bits) so equal corners share one PLY vertex.
  std::vector<Eigen::Vector3d> positions, vertex_normals;
  std::vector<uint32_t> indices;
  std::map<std::tuple<int, float, float, float>, uint32_t> vertex_of;
  for (size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int p = mesh.triangles[t][k];
      const Eigen::Vector3d n = normals ? mesh.corner_normals[3 * t + k] : Eigen::Vector3d::Zero();
      const auto key = std::make_tuple(p, float(n.x()), float(n.y()), float(n.z()));
      auto [it, added] = vertex_of.emplace(key, static_cast<uint32_t>(positions.size()));
      if (added) {
        positions.push_back(mesh.positions[p]);
        vertex_normals.push_back(n);
      }
      indices.push_back(it->second);
    }
  std::string out = "ply\nformat binary_little_endian 1.0\n";
  if (!comment.empty()) out += "comment " + comment + "\n";
  out += "element vertex " + std::to_string(positions.size()) + "\nproperty float x\nproperty float y\nproperty float z\n";
  if (normals) out += "property float nx\nproperty float ny\nproperty float nz\n";
  out += "element face " + std::to_string(mesh.triangles.size()) + "\nproperty list uchar uint vertex_indices\nend_header\n";
  for (size_t i = 0; i < positions.size(); ++i) {
    for (int c = 0; c < 3; ++c) put_float(out, positions[i][c]);
    if (normals)
      for (int c = 0; c < 3; ++c) put_float(out, vertex_normals[i][c]);
  }
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    out.push_back(static_cast<char>(3));
    for (int k = 0; k < 3; ++k) put_uint(out, indices[3 * t + k]);
  }
  return out;
}

void write_ply(const std::string& path, const TriangleMesh& mesh, const std::string& comment) {
  try {
    write_file_atomically(path, format_ply(mesh, comment));
  } catch (const GeometryError& e) {
    throw FileError(path + ": " + e.what());
  }
}

}  // namespace cadnurbs
