#pragma once
// One glTF primitive as EXT_meshopt_compression and KHR_mesh_quantization store it (the way gltfpack
// does): positions as unsigned 16-bit grid coordinates, 8 bytes a vertex (x, y, z, padding), triangles
// reordered for the vertex cache and vertices for fetch order, then meshoptimizer's vertex codec
// (version 0) and triangle index codec.
#include <array>
#include <cstdint>
#include <string>

#include "formats/gltf/node_primitives.hpp"
#include "formats/gltf/position_grid.hpp"

namespace cadnurbs {

struct MeshoptPrimitive {
  static constexpr int vertex_stride = 8;
  std::string vertex_stream;  // meshopt_encodeVertexBuffer of `vertices` quantised vertices
  std::string index_stream;   // meshopt_encodeIndexBuffer of `indices` indices
  long vertices = 0, indices = 0;
  int index_size = 2;                                // bytes per decoded index: 2 when vertices <= 65535, else 4
  std::array<std::uint32_t, 3> min{}, max{};         // of the grid coordinates (the accessor's min / max)
};

// Refuses (std::invalid_argument) a grid of more than 16 bits, which unsigned 16-bit values cannot hold.
MeshoptPrimitive meshopt_primitive(const PrimitiveMesh& mesh, const PositionGrid& grid);

}  // namespace cadnurbs
