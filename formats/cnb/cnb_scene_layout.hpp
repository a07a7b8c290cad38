#pragma once
// Flag bits of the scene tree records (docs/cnb.md, "Scene tree"), shared by the writer and the reader.
#include <cstdint>

namespace cadnurbs::cnb {

// Node flags.
// node_exact_numbers_flag: the transform's numbers are coded by write_exact_number, not as raw float64.
constexpr uint8_t node_colour_flag = 1, node_linear_flag = 2, node_translation_flag = 4, node_exact_numbers_flag = 8;
// Shape kind byte: the geometry's kind (0 trimmed surface, 1 3D curve, 2 triangle mesh, 3 polygon mesh,
// the order of core::Geometry; 4: the same geometry as an earlier shape) in the low bits, this bit when
// the shape has its own colour.
constexpr uint8_t repeated_shape_kind = 4;
// 5: a triangle mesh coded by a traversal (write_traversal_mesh); decoded as core's TriangleMesh.
constexpr uint8_t traversal_mesh_kind = 5;
// 6: a group of shapes whose triangle meshes are coded together (write_mesh_group); the node's shape count
// counts each of them.
constexpr uint8_t mesh_group_kind = 6;
// 7 (format version 5 on): a mesh group whose union is followed by copies of pieces (cnb_mesh_copies.hpp).
constexpr uint8_t mesh_group_with_copies_kind = 7;
constexpr uint8_t has_colour_flag = 0x10;
// Repeated shapes make the decoded scene larger than its payload: it may hold at most this many numbers
// (coordinates, knots, weights, indices) per payload byte, plus a fixed allowance, so that a small file
// cannot claim a huge scene. (A part placed a thousand times costs about ten bytes a copy: far within.)
constexpr size_t numbers_per_payload_byte = 256;
constexpr size_t numbers_allowance = size_t(1) << 20;
// Deeper node trees are refused (a crafted file must not exhaust the reader's stack).
constexpr int deepest_node = 1000;

}  // namespace cadnurbs::cnb
