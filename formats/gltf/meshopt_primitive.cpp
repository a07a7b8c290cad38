#include "formats/gltf/meshopt_primitive.hpp"

#include <meshoptimizer.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace cadnurbs {
namespace {

struct QuantisedVertex {
  std::uint16_t x, y, z, padding;
};
static_assert(sizeof(QuantisedVertex) == MeshoptPrimitive::vertex_stride);

}  // namespace

MeshoptPrimitive meshopt_primitive(const PrimitiveMesh& mesh, const PositionGrid& grid) {
  if (grid.bits > 16)
    throw std::invalid_argument("meshopt glTF: " + std::to_string(grid.bits) + " position bits do not fit 16-bit integers");
  std::vector<QuantisedVertex> vertices;
  vertices.reserve(mesh.positions.size());
  for (const auto& p : mesh.positions) {
    const auto q = grid.quantised(p);
    vertices.push_back({static_cast<std::uint16_t>(q[0]), static_cast<std::uint16_t>(q[1]),
                        static_cast<std::uint16_t>(q[2]), 0});
  }
  std::vector<unsigned int> indices(mesh.indices.begin(), mesh.indices.end());
  meshopt_optimizeVertexCache(indices.data(), indices.data(), indices.size(), vertices.size());
  std::vector<QuantisedVertex> fetched(vertices.size());
  fetched.resize(meshopt_optimizeVertexFetch(fetched.data(), indices.data(), indices.size(), vertices.data(),
                                             vertices.size(), sizeof(QuantisedVertex)));

  MeshoptPrimitive result;
  result.vertices = static_cast<long>(fetched.size());
  result.indices = static_cast<long>(indices.size());
  result.index_size = fetched.size() <= 65535 ? 2 : 4;  // 65535 itself is reserved (primitive restart)
  result.min = {0xffff, 0xffff, 0xffff};
  for (const auto& v : fetched) {
    const std::array<std::uint32_t, 3> q{v.x, v.y, v.z};
    for (int axis = 0; axis < 3; ++axis) {
      result.min[axis] = std::min(result.min[axis], q[axis]);
      result.max[axis] = std::max(result.max[axis], q[axis]);
    }
  }
  std::vector<unsigned char> buffer(meshopt_encodeVertexBufferBound(fetched.size(), sizeof(QuantisedVertex)));
  buffer.resize(meshopt_encodeVertexBuffer(buffer.data(), buffer.size(), fetched.data(), fetched.size(),
                                           sizeof(QuantisedVertex)));
  result.vertex_stream.assign(buffer.begin(), buffer.end());
  buffer.assign(meshopt_encodeIndexBufferBound(indices.size(), fetched.size()), 0);
  buffer.resize(meshopt_encodeIndexBuffer(buffer.data(), buffer.size(), indices.data(), indices.size()));
  result.index_stream.assign(buffer.begin(), buffer.end());
  return result;
}

}  // namespace cadnurbs
