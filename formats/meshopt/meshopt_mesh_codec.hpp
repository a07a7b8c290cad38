#pragma once
// A triangle mesh stored the way gltfpack stores one with meshoptimizer (0.18): positions quantised to
// integers on one uniform grid, vertex cache and vertex fetch order, then meshopt_encodeVertexBuffer
// and meshopt_encodeIndexBuffer (index codec version 1). These codecs leave redundancy for a general
// compressor on purpose: the size people compare is gzip of the bytes (formats/common/gzip.hpp),
// which the caller takes.
//
// The mesh is taken as given: no welding here (weld it first, e.g. with analysis/mesh/weld_exact, or the
// index codec sees a triangle soup).
//
// Bytes (little-endian): "CNMO", version 1 (uint8), position bits (uint8), vertex count and triangle
// count (uint32 each), grid origin x, y, z and grid step (float64 each), length of the vertex stream
// (uint32), the vertex stream, the index stream (to the end). A vertex is 4 x uint16 (x, y, z, 0) for
// up to 16 bits, 3 x uint32 above (meshopt wants a multiple of 4 bytes).
//
// The grid: origin = the bounding box's minimum corner, step = its LARGEST extent / (2^bits - 1), the
// same on all axes (1 when all points coincide); a vertex goes to the nearest grid point, so it moves
// at most step/2 along each axis, step * sqrt(3) / 2 in all.
#include <string>
#include <vector>

#include "core/triangle_mesh.hpp"

namespace cadnurbs {

// The bytes described above. position_bits: 1..30. Vertices no triangle uses are dropped (vertex fetch
// order keeps only used ones); triangle and vertex order change. Throws GeometryError (entity
// "meshopt mesh") for an invalid or empty mesh, or bits out of range.
std::string encode_meshopt_mesh(const TriangleMesh& mesh, int position_bits);

// The mesh in `bytes` (grid points as doubles, the stored vertex and triangle order, no normals).
// Throws FileError "<name>: <reason>" for a short or foreign header, counts the data cannot hold,
// streams meshopt cannot decode, indices out of range, or values outside the grid.
TriangleMesh decode_meshopt_mesh(const std::string& bytes, const std::string& name);

// The grid point each vertex of `mesh` goes to at `position_bits` (same order): bit for bit the
// position decode_meshopt_mesh returns for it.
std::vector<Eigen::Vector3d> meshopt_quantised_positions(const TriangleMesh& mesh, int position_bits);

}  // namespace cadnurbs
