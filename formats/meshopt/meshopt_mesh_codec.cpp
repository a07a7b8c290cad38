#include "formats/meshopt/meshopt_mesh_codec.hpp"

#include <meshoptimizer.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <mutex>

#include "core/geometry_error.hpp"
#include "formats/common/file_io.hpp"

namespace cadnurbs {

namespace {

const char* const kEntity = "meshopt mesh";
const char kMagic[4] = {'C', 'N', 'M', 'O'};
constexpr uint8_t kVersion = 1;
constexpr size_t kHeaderSize = 4 + 1 + 1 + 4 + 4 + 4 * 8 + 4;

// The uniform grid over a mesh's bounding box (see the header).
struct Grid {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  double step = 1;
  uint32_t max_value = 1;  // 2^bits - 1

  Eigen::Vector3d point(const std::array<uint32_t, 3>& q) const {
    return {origin.x() + q[0] * step, origin.y() + q[1] * step, origin.z() + q[2] * step};
  }
  std::array<uint32_t, 3> nearest(const Eigen::Vector3d& p) const {
    std::array<uint32_t, 3> q{};
    for (int c = 0; c < 3; ++c) {
      const double v = std::round((p[c] - origin[c]) / step);
      q[c] = static_cast<uint32_t>(std::clamp(v, 0.0, static_cast<double>(max_value)));
    }
    return q;
  }
};

void check_bits(int position_bits) {
  if (position_bits < 1 || position_bits > 30)
    throw GeometryError(kEntity, "position bits " + std::to_string(position_bits) + " outside 1..30");
}

Grid grid_over(const TriangleMesh& mesh, int position_bits) {
  Grid grid;
  grid.max_value = (uint32_t(1) << position_bits) - 1;
  if (mesh.positions.empty()) return grid;
  Eigen::Vector3d lo = mesh.positions[0], hi = lo;
  for (const auto& p : mesh.positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double extent = (hi - lo).maxCoeff();
  grid.origin = lo;
  grid.step = extent > 0 ? extent / grid.max_value : 1.0;
  return grid;
}

size_t vertex_size(int position_bits) { return position_bits <= 16 ? 8 : 12; }

void put_u32(std::string& out, uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
}
void put_f64(std::string& out, double v) {
  const auto bits = std::bit_cast<uint64_t>(v);
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<char>((bits >> (8 * i)) & 0xff));
}
uint64_t get_le(const std::string& bytes, size_t at, int count) {
  uint64_t v = 0;
  for (int i = 0; i < count; ++i) v |= uint64_t(static_cast<unsigned char>(bytes[at + i])) << (8 * i);
  return v;
}

// The vertex as stored: x, y, z in 16 bits plus a zero pad, or in 32 bits.
void store_vertex(unsigned char* at, const std::array<uint32_t, 3>& q, size_t size) {
  if (size == 8) {
    const uint16_t v[4] = {static_cast<uint16_t>(q[0]), static_cast<uint16_t>(q[1]), static_cast<uint16_t>(q[2]), 0};
    std::memcpy(at, v, sizeof v);
  } else {
    std::memcpy(at, q.data(), 12);
  }
}
std::array<uint32_t, 3> load_vertex(const unsigned char* at, size_t size) {
  std::array<uint32_t, 3> q{};
  if (size == 8) {
    uint16_t v[4];
    std::memcpy(v, at, sizeof v);
    q = {v[0], v[1], v[2]};
  } else {
    std::memcpy(q.data(), at, 12);
  }
  return q;
}

}  // namespace

std::string encode_meshopt_mesh(const TriangleMesh& mesh, int position_bits) {
  validate(mesh, kEntity);
  check_bits(position_bits);
  if (mesh.triangles.empty()) throw GeometryError(kEntity, "no triangles");
  static_assert(std::endian::native == std::endian::little, "vertex records are written in host order");
  // Version 1 (meshoptimizer 0.14+) codes triangles better; gltfpack writes it too. Global state of the
  // library, hence once.
  static std::once_flag index_version;
  std::call_once(index_version, [] { meshopt_encodeIndexVersion(1); });

  const Grid grid = grid_over(mesh, position_bits);
  const size_t size = vertex_size(position_bits);
  const size_t n = mesh.positions.size();
  std::vector<unsigned char> vertices(n * size);
  for (size_t i = 0; i < n; ++i) store_vertex(&vertices[i * size], grid.nearest(mesh.positions[i]), size);

  std::vector<unsigned> indices;
  indices.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) indices.push_back(static_cast<unsigned>(t[k]));
  std::vector<unsigned> cache_order(indices.size());
  meshopt_optimizeVertexCache(cache_order.data(), indices.data(), indices.size(), n);
  std::vector<unsigned char> fetch_order(n * size);
  const size_t used = meshopt_optimizeVertexFetch(fetch_order.data(), cache_order.data(), cache_order.size(),
                                                  vertices.data(), n, size);

  std::vector<unsigned char> vertex_stream(meshopt_encodeVertexBufferBound(used, size));
  vertex_stream.resize(
      meshopt_encodeVertexBuffer(vertex_stream.data(), vertex_stream.size(), fetch_order.data(), used, size));
  std::vector<unsigned char> index_stream(meshopt_encodeIndexBufferBound(cache_order.size(), used));
  index_stream.resize(
      meshopt_encodeIndexBuffer(index_stream.data(), index_stream.size(), cache_order.data(), cache_order.size()));
  if (vertex_stream.empty() || index_stream.empty()) throw GeometryError(kEntity, "meshoptimizer cannot encode it");

  std::string out(kMagic, 4);
  out.push_back(static_cast<char>(kVersion));
  out.push_back(static_cast<char>(position_bits));
  put_u32(out, static_cast<uint32_t>(used));
  put_u32(out, static_cast<uint32_t>(mesh.triangles.size()));
  for (int c = 0; c < 3; ++c) put_f64(out, grid.origin[c]);
  put_f64(out, grid.step);
  put_u32(out, static_cast<uint32_t>(vertex_stream.size()));
  out.append(vertex_stream.begin(), vertex_stream.end());
  out.append(index_stream.begin(), index_stream.end());
  return out;
}

TriangleMesh decode_meshopt_mesh(const std::string& bytes, const std::string& name) {
  auto refuse = [&name](const std::string& reason) { return FileError(name + ": " + reason); };
  if (bytes.size() < kHeaderSize) throw refuse("too short for a meshopt mesh header");
  if (bytes.compare(0, 4, kMagic, 4) != 0) throw refuse("not a cadnurbs meshopt mesh (no CNMO signature)");
  if (static_cast<uint8_t>(bytes[4]) != kVersion)
    throw refuse("meshopt mesh version " + std::to_string(static_cast<uint8_t>(bytes[4])) + " is not supported");
  const int bits = static_cast<uint8_t>(bytes[5]);
  if (bits < 1 || bits > 30) throw refuse("position bits " + std::to_string(bits) + " outside 1..30");
  const auto vertex_count = static_cast<size_t>(get_le(bytes, 6, 4));
  const auto triangle_count = static_cast<size_t>(get_le(bytes, 10, 4));
  Grid grid;
  grid.max_value = (uint32_t(1) << bits) - 1;
  for (int c = 0; c < 3; ++c) grid.origin[c] = std::bit_cast<double>(get_le(bytes, 14 + 8 * c, 8));
  grid.step = std::bit_cast<double>(get_le(bytes, 38, 8));
  const uint32_t far = grid.max_value;
  if (!grid.origin.allFinite() || !(grid.step > 0) || !grid.point({far, far, far}).allFinite())
    throw refuse("grid origin, step or far corner is not finite, or the step is not positive");
  const auto vertex_bytes = static_cast<size_t>(get_le(bytes, 46, 4));
  if (vertex_bytes > bytes.size() - kHeaderSize) throw refuse("vertex stream runs past the end");
  const size_t index_bytes = bytes.size() - kHeaderSize - vertex_bytes;
  const size_t size = vertex_size(bits);
  // meshopt spends at least 2 bits per byte of a vertex per 16 vertices, and 1 byte per triangle: a
  // count beyond that is damage, refused before it allocates anything.
  if (vertex_count == 0 || triangle_count == 0) throw refuse("no vertices or no triangles");
  if (vertex_count * size > 64 * vertex_bytes) throw refuse("vertex count exceeds what its stream can hold");
  if (triangle_count > index_bytes) throw refuse("triangle count exceeds what its stream can hold");

  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data()) + kHeaderSize;
  std::vector<unsigned char> vertices(vertex_count * size);
  if (const int rc = meshopt_decodeVertexBuffer(vertices.data(), vertex_count, size, data, vertex_bytes))
    throw refuse("damaged vertex stream (meshoptimizer error " + std::to_string(rc) + ")");
  std::vector<unsigned> indices(3 * triangle_count);
  if (const int rc = meshopt_decodeIndexBuffer(indices.data(), indices.size(), sizeof(unsigned), data + vertex_bytes,
                                               index_bytes))
    throw refuse("damaged index stream (meshoptimizer error " + std::to_string(rc) + ")");

  TriangleMesh mesh;
  mesh.positions.reserve(vertex_count);
  for (size_t i = 0; i < vertex_count; ++i) {
    const std::array<uint32_t, 3> q = load_vertex(&vertices[i * size], size);
    if (q[0] > grid.max_value || q[1] > grid.max_value || q[2] > grid.max_value)
      throw refuse("vertex " + std::to_string(i) + " lies outside its " + std::to_string(bits) + "-bit grid");
    mesh.positions.push_back(grid.point(q));
  }
  mesh.triangles.reserve(triangle_count);
  for (size_t t = 0; t < triangle_count; ++t) {
    std::array<int, 3> tri{};
    for (int k = 0; k < 3; ++k) {
      if (indices[3 * t + k] >= vertex_count)
        throw refuse("triangle " + std::to_string(t) + " refers to a missing vertex");
      tri[k] = static_cast<int>(indices[3 * t + k]);
    }
    mesh.triangles.push_back(tri);
  }
  return mesh;
}

std::vector<Eigen::Vector3d> meshopt_quantised_positions(const TriangleMesh& mesh, int position_bits) {
  check_bits(position_bits);
  const Grid grid = grid_over(mesh, position_bits);
  std::vector<Eigen::Vector3d> out;
  out.reserve(mesh.positions.size());
  for (const auto& p : mesh.positions) out.push_back(grid.point(grid.nearest(p)));
  return out;
}

}  // namespace cadnurbs
